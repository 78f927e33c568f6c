#pragma once
// Scene files: takes the text of a .surf file (TOML), a path, a `--set KEY=VALUE` assignment
// or a bare formula, and puts out a validated Scene, or a SceneError that names the file,
// line, column and key, with a hint and the offending source line for a caret. Nothing here
// throws. saveScene writes the opposite way: every key, so that parseScene(saveScene(s))
// gives back s exactly. The format and every key are documented in docs/surf-format.md.
#include <filesystem>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "expr/graph.hpp"
#include "parser/parser.hpp"
#include "scene/scene.hpp"

namespace zs {

struct SceneError {
  std::string file;  // the scene's file name, "--set" or "<formula>"
  int line = 0;      // 1-based; 0 when the error has no place in a text (unreadable file)
  int column = 0;    // 1-based, counted in code points like toml++ does
  std::string key;   // dotted key ("camera.fov_y"); empty for TOML syntax errors
  std::string message;
  std::string hint;        // may be empty
  std::string sourceLine;  // the line holding the error, for the caret; may be empty
  int width = 1;           // code points the caret underlines

  bool operator==(const SceneError&) const = default;
};

using SceneResult = std::variant<Scene, SceneError>;

// A scene read from another program's file (SURFER's .jsurf, surf's scripts): the scene, and
// warnings for what zeroset shows differently, in file order (print them as warnings).
struct ImportedScene {
  Scene scene;
  std::vector<SceneError> warnings;
};

using ImportResult = std::variant<ImportedScene, SceneError>;

// Parses and validates a whole .surf text; `fileName` is only used in errors.
SceneResult parseScene(std::string_view text, std::string_view fileName);

// Reads the file and parses it; a missing or unreadable file is a SceneError with line 0.
SceneResult loadScene(const std::filesystem::path& path);

// The whole text of a scene-sized file (a .surf, a .jsurf, a surf script); `what` names
// the kind in the errors ("cannot open scene file: ..."): a directory, a missing or
// unreadable file, or one over 16 MiB is a SceneError with line 0.
std::variant<std::string, SceneError> readSceneFile(const std::filesystem::path& path,
                                                    std::string_view what);

// An importer's scene must be one a .surf file may hold: nothing, or the error that says it
// is not (a bug in the importer, named by `importer`, e.g. "SURFER .jsurf").
std::optional<SceneError> checkImportedScene(const Scene& scene, std::string_view fileName,
                                             std::string_view importer);

// As formatSceneError, with "warning" for "error" (an importer's notes).
std::string formatSceneWarning(const SceneError& warning);

// A scene file when `arg` names an existing file or ends in ".surf"; otherwise `arg` is a
// formula, and the scene holds it with every other setting at its default.
SceneResult loadSceneOrFormula(std::string_view arg);

// Applies one command-line assignment such as `camera.eye=[0,0,3]` or `formula="x^2-y"`:
// KEY is a dotted scene key, VALUE a TOML value (an inline table also works for a table
// key). Same validation and hints as a file; errors name the file "--set". On error the
// scene is left unchanged.
std::optional<SceneError> applyOverride(Scene& scene, std::string_view assignment);

// Several assignments in order, as `--set` options: each is read and validated as above, but
// keys that constrain each other (domain min and max; camera eye, target and up) are checked
// once, after the last, so no order of the assignments is wrong. The error points at the
// latest assignment of the keys involved. On error the scene is left unchanged.
std::optional<SceneError> applyOverrides(Scene& scene, std::span<const std::string> assignments);

// A complete .surf text holding every key of `scene`, doubles in shortest round-trip form.
std::string saveScene(const Scene& scene);

//   scene.surf:3:14: error: message
//     formula = "x^^2"
//                  ^
//     hint: ...
std::string formatSceneError(const SceneError& error);

// The surfaces of a scene (scene/surfaces.cpp). Surface 0 is the scene's own formula, level
// and render.materials; surfaces 1.. are moreSurfaces.

// How many surfaces the scene draws (1 + moreSurfaces), and surface i as an entry.
std::size_t surfaceCount(const Scene& scene);
SurfaceEntry surfaceAt(const Scene& scene, std::size_t i);

// The default materials of surface i: each surface its own colors.
Materials surfaceMaterials(std::size_t i);

// Appends a surface with this formula and its default materials; "" on success, else the
// formula's caret error or why no more surfaces fit, ready to print.
std::string addSurface(Scene& scene, std::string_view formula);

// Surface i parsed as the function whose zero set is drawn: F - level (F itself at level 0).
// Errors point into that surface's formula.
ParseResult parseSurfaceFormula(const Scene& scene, std::size_t i);

// The function whose zero set is the whole picture: surface 0's, or for several surfaces the
// product of theirs, whose zero set is their union. On error `failedSurface` (when given)
// says which surface's formula the error points into; on success `surfaceRoots` (when given)
// holds each surface's function as a node of the result's graph.
ParseResult parseSceneFormula(const Scene& scene, std::size_t* failedSurface = nullptr,
                              std::vector<NodeId>* surfaceRoots = nullptr);

// The scene with surface i alone: its formula, level and materials in the scene's own
// fields, every other setting kept (what the per-surface commands work on).
Scene surfaceScene(const Scene& scene, std::size_t i);

// The parser's error placed under the formula of `surface`, named when there are several.
std::string formatSceneFormulaError(const Scene& scene, std::size_t surface,
                                    const ParseError& error);

// The values of the formula's parameters in graph.params() order: the scene's value where
// it has one, kDefaultParamValue otherwise.
std::vector<double> paramValues(const Scene& scene, const Graph& graph);

// Every dotted leaf key a scene file may hold (params.NAME excluded), in file order: for
// completion in the prompt and for checking the documentation.
std::vector<std::string> sceneKeys();

}  // namespace zs
