#include "render/program_cache.hpp"

#include <glad/gl.h>

#include <algorithm>
#include <utility>

#include "render/shader_program.hpp"

namespace zs {

ProgramCache::~ProgramCache() {
  dropAll();
}

unsigned ProgramCache::rebuild(std::string_view vertex, std::string_view fragment,
                               const ProgramVariant& first, std::string& log) {
  std::map<ProgramVariant, unsigned> previous;
  std::swap(previous, programs_);
  std::string oldVertex = std::exchange(vertex_, std::string(vertex));
  std::string oldFragment = std::exchange(fragment_, std::string(fragment));
  const unsigned program = get(first, log);
  if (!program) {  // keep what worked before
    dropAll();
    programs_ = std::move(previous);
    vertex_ = std::move(oldVertex);
    fragment_ = std::move(oldFragment);
    return 0;
  }
  for (auto& [variant, old] : previous) drop(old);
  hasBeam_ = fragment_.find("\n#define RT_HAS_BEAM\n") != std::string::npos;
  return program;
}

unsigned ProgramCache::get(const ProgramVariant& v, std::string& log) {
  if (auto it = programs_.find(v); it != programs_.end()) return it->second;
  const unsigned p =
      compileProgram(withFrameStorage(vertex_, storage_),
                     withFrameStorage(withVariantDefines(fragment_, v), storage_), log);
  if (!p) return 0;
  // Editing a light makes a new variant each time: keep only the current lighting's.
  for (auto it = programs_.begin(); it != programs_.end();) {
    if (it->first.shading == v.shading) {
      ++it;
      continue;
    }
    drop(it->second);
    it = programs_.erase(it);
  }
  programs_.emplace(v, p);
  return p;
}

int ProgramCache::uniform(unsigned program, const char* name) {
  auto& cache = locations_[program];
  auto it = cache.find(name);
  if (it == cache.end()) it = cache.emplace(name, glGetUniformLocation(program, name)).first;
  return it->second;
}

void ProgramCache::setFrameStorage(FrameStorage storage) {
  if (storage == storage_) return;
  storage_ = storage;
  dropAll();
}

void ProgramCache::drop(unsigned program) {
  glDeleteProgram(program);
  locations_.erase(program);  // GL may hand the id out again
}

void ProgramCache::dropAll() {
  for (auto& [variant, p] : programs_) drop(p);
  programs_.clear();
}

}  // namespace zs
