// The nesting of a JSON text, measured before it is parsed. nlohmann's dump() and tinygltf's
// conversion of a parsed value recurse once per level: a scene nested 300,000 deep crashed
// grass-render, a glTF whose "extras" nested 20,000 deep crashed it in tinygltf, and 5,000
// deep crashed the ASan build (issue 37). A text nested deeper than kMaxJsonDepth is refused
// before any parser sees it.
#pragma once

#include <cstddef>
#include <string>

namespace grass_sample {

// The deepest nesting of arrays and objects a scene file or glTF JSON may have. The sample
// scenes nest 5 deep, a glTF file's own structure 6; "extras" are free but rarely deeper.
constexpr int kMaxJsonDepth = 100;

// Empty when the text nests at most `max_depth` arrays and objects; otherwise where it goes
// deeper ("nests deeper than 100 levels (at byte 123)"). Counts '[' and '{' outside strings
// (with their escapes) and, when `comments` is set, outside // and /* */ comments (the scene
// files allow them). Does not check that the text is valid JSON: the parser does.
std::string json_depth_problem(const char* text, size_t size, int max_depth, bool comments);

} // namespace grass_sample
