#pragma once
// The ray tracer's programs: takes the vertex and fragment source of one surface and puts out
// linked GL programs, one per variant (the features that are compile-time in the shader:
// supersampling, kept hits, reflection, lights and coloring, the beam pass and its tile
// mask), each compiled the first time a frame needs it, with its uniform locations looked up
// once. Needs a current GL context; every program belongs to it.
#include <map>
#include <string>
#include <string_view>
#include <tuple>
#include <unordered_map>

#include "render/program_variant.hpp"
#include "render/settings.hpp"

namespace zs {

class ProgramCache {
 public:
  ProgramCache() = default;
  ~ProgramCache();
  ProgramCache(const ProgramCache&) = delete;
  ProgramCache& operator=(const ProgramCache&) = delete;

  // New sources: compiles `first` of them at once, so a broken shader is reported here;
  // on failure returns 0 with `log` set and keeps the previous sources and programs.
  unsigned rebuild(std::string_view vertex, std::string_view fragment, const ProgramVariant& first,
                   std::string& log);
  bool holds(std::string_view vertex, std::string_view fragment) const {
    return !programs_.empty() && vertex == vertex_ && fragment == fragment_;
  }
  // The shader has a beam pass (the interval method: shader_assembly.cpp's RT_HAS_BEAM).
  bool hasBeam() const { return hasBeam_; }

  // The program of `v`, compiled if needed; 0 with `log` set when it does not compile (the
  // variants that do stay). A new lighting drops the programs of the others.
  unsigned get(const ProgramVariant& v, std::string& log);
  // The location of `name` in `program` (-1: none), looked up once per program.
  int uniform(unsigned program, const char* name);

  // How the programs' stages pass the frame's parameters; a change drops every program.
  void setFrameStorage(FrameStorage storage);
  FrameStorage frameStorage() const { return storage_; }

 private:
  void drop(unsigned program);
  void dropAll();

  std::string vertex_, fragment_;
  bool hasBeam_ = false;
  FrameStorage storage_ = FrameStorage::FlatVaryings;
  std::map<ProgramVariant, unsigned> programs_;
  std::unordered_map<unsigned, std::unordered_map<std::string, int>> locations_;
};

}  // namespace zs
