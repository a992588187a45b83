// Command lines of the samples and tools, through CLI11: the parse with the tools' exit codes and
// the options more than one tool has (backend, image size, points, ranges).
#pragma once

#include <grass/grass.h>

#include <CLI/CLI.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace grass_sample {

// Parses the command line. -1: go on; otherwise the tool's exit status: 0 after --help, 2
// after an unknown option or a bad value (the error, naming the option and the value, and a
// pointer to --help on stderr).
int parse(CLI::App& app, int argc, char** argv);

// "gl" or "vk" (also "vulkan"); false for anything else.
bool parse_backend(const std::string& text, grass_backend* out);
const char* backend_name(grass_backend backend);

// --backend gl|vk into *out.
CLI::Option* add_backend_option(CLI::App& app, grass_backend* out, const std::string& help = "GPU backend: gl or vk");

// --size WxH into *width and *height, each in min..max.
CLI::Option* add_size_option(CLI::App& app, uint32_t* width, uint32_t* height, uint32_t min, uint32_t max,
                             const std::string& help);

// `name` X,Y,Z (finite numbers) into out; *given set when the option is on the command line.
CLI::Option* add_point_option(CLI::App& app, const std::string& name, double out[3], bool* given,
                              const std::string& help);

// --blade-culling TESTS into *tests: the names of jahrmann2017 6.2's per-blade tests
// (orientation, frustum, distance-index, distance-threshold), repeatable or comma-separated.
// `what`: the tool's words for the field it applies to.
CLI::Option* add_blade_culling_option(CLI::App& app, std::vector<std::string>* tests, const std::string& what);
// Those tests switched on at Jahrmann's values (the distance tests thin over the field's
// geometry tiers); the rest at grass_default_blade_culling_desc().
grass_blade_culling_desc blade_culling_desc(const std::vector<std::string>& tests);

// --tessellation PX: the blades' dynamic tessellation (grass_set_blade_tessellation) `what`,
// with error_pixels PX; 0 (the default): off.
CLI::Option* add_tessellation_option(CLI::App& app, float* error_pixels, const std::string& what);
// Sets it on `field` (nothing when error_pixels is 0).
grass_result set_tessellation(grass_context* ctx, grass_field_id field, float error_pixels);

// A value strictly between lo and hi (CLI::Range includes its ends).
CLI::Validator open_range(double lo, double hi);
// A value in lo..hi, ends included: CLI::Range, but NaN refused (CLI::Range lets it through:
// "--density nan" was taken and then ignored).
CLI::Validator closed_range(double lo, double hi);
// A number no smaller than lo.
CLI::Validator at_least(double lo);

} // namespace grass_sample
