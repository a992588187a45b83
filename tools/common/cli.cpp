#include "cli.hpp"

#include <cmath>
#include <cstdio>

namespace grass_sample {

int parse(CLI::App& app, int argc, char** argv) {
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        return app.exit(e) == 0 ? 0 : 2;
    }
    return -1;
}

bool parse_backend(const std::string& text, grass_backend* out) {
    if (text == "gl") {
        *out = GRASS_BACKEND_GL;
    } else if (text == "vk" || text == "vulkan") {
        *out = GRASS_BACKEND_VULKAN;
    } else {
        return false;
    }
    return true;
}

const char* backend_name(grass_backend backend) {
    return backend == GRASS_BACKEND_VULKAN ? "vk" : backend == GRASS_BACKEND_GL ? "gl" : "none";
}

CLI::Option* add_backend_option(CLI::App& app, grass_backend* out, const std::string& help) {
    const CLI::Validator is_backend(
        [](std::string& text) {
            grass_backend b;
            return parse_backend(text, &b) ? std::string() : "\"" + text + "\" is not a backend (gl or vk)";
        },
        "gl|vk");
    return app
        .add_option_function<std::string>(
            "--backend", [out](const std::string& text) { parse_backend(text, out); }, help)
        ->check(is_backend)
        ->default_str(backend_name(*out));
}

CLI::Option* add_size_option(CLI::App& app, uint32_t* width, uint32_t* height, uint32_t min, uint32_t max,
                             const std::string& help) {
    const CLI::Validator is_size(
        [min, max](std::string& text) {
            unsigned w = 0, h = 0;
            char tail = 0;
            if (std::sscanf(text.c_str(), "%ux%u%c", &w, &h, &tail) != 2 || w < min || h < min || w > max || h > max) {
                return "\"" + text + "\" is not WxH with " + std::to_string(min) + ".." + std::to_string(max) + " each";
            }
            return std::string();
        },
        "WxH");
    return app
        .add_option_function<std::string>(
            "--size", [width, height](const std::string& text) { std::sscanf(text.c_str(), "%ux%u", width, height); },
            help)
        ->check(is_size)
        ->default_str(std::to_string(*width) + "x" + std::to_string(*height));
}

CLI::Option* add_point_option(CLI::App& app, const std::string& name, double out[3], bool* given,
                              const std::string& help) {
    const CLI::Validator is_point(
        [](std::string& text) {
            double p[3];
            char tail = 0;
            if (std::sscanf(text.c_str(), "%lf,%lf,%lf%c", &p[0], &p[1], &p[2], &tail) != 3 || !std::isfinite(p[0]) ||
                !std::isfinite(p[1]) || !std::isfinite(p[2])) {
                return "\"" + text + "\" is not X,Y,Z (three finite numbers)";
            }
            return std::string();
        },
        "X,Y,Z");
    return app
        .add_option_function<std::string>(
            name,
            [out, given](const std::string& text) {
                std::sscanf(text.c_str(), "%lf,%lf,%lf", &out[0], &out[1], &out[2]);
                *given = true;
            },
            help)
        ->check(is_point);
}

CLI::Validator open_range(double lo, double hi) {
    return CLI::Validator(
        [lo, hi](std::string& text) {
            double v = 0.0;
            if (!CLI::detail::lexical_cast(text, v) || !(v > lo && v < hi)) {
                return "\"" + text + "\" is not between " + CLI::detail::to_string(lo) + " and " +
                       CLI::detail::to_string(hi) + " (exclusive)";
            }
            return std::string();
        },
        "(" + CLI::detail::to_string(lo) + ", " + CLI::detail::to_string(hi) + ")");
}

CLI::Validator closed_range(double lo, double hi) {
    return CLI::Validator(
        [lo, hi](std::string& text) {
            double v = 0.0;
            if (!CLI::detail::lexical_cast(text, v) || !(v >= lo && v <= hi)) {
                return "\"" + text + "\" is not between " + CLI::detail::to_string(lo) + " and " +
                       CLI::detail::to_string(hi);
            }
            return std::string();
        },
        "[" + CLI::detail::to_string(lo) + ", " + CLI::detail::to_string(hi) + "]");
}

CLI::Validator at_least(double lo) {
    return CLI::Validator(
        [lo](std::string& text) {
            double v = 0.0;
            if (!CLI::detail::lexical_cast(text, v) || !(v >= lo)) {
                return "\"" + text + "\" is less than " + CLI::detail::to_string(lo);
            }
            return std::string();
        },
        ">=" + CLI::detail::to_string(lo));
}

CLI::Option* add_blade_culling_option(CLI::App& app, std::vector<std::string>* tests, const std::string& what) {
    return app
        .add_option("--blade-culling", *tests,
                    "per-blade culling " + what +
                        " (jahrmann2017 6.2), at his values: orientation, frustum, distance-index or "
                        "distance-threshold (repeatable or comma-separated)")
        ->delimiter(',')
        ->check(CLI::IsMember({"orientation", "frustum", "distance-index", "distance-threshold"}));
}

CLI::Option* add_tessellation_option(CLI::App& app, float* error_pixels, const std::string& what) {
    return app
        .add_option("--tessellation", *error_pixels,
                    "the blades' dynamic tessellation " + what +
                        " (jahrmann2017 6.3): the most a coarser level may move a blade's outline on screen, "
                        "pixels (DEFAULT's 0.5); 0: off")
        ->capture_default_str()
        ->check(closed_range(0.0, 16.0));
}

grass_result set_tessellation(grass_context* ctx, grass_field_id field, float error_pixels) {
    if (error_pixels == 0.0f) return GRASS_SUCCESS;
    grass_blade_tessellation_desc t = grass_default_blade_tessellation_desc();
    t.enabled = 1;
    t.error_pixels = error_pixels;
    return grass_set_blade_tessellation(ctx, field, &t);
}

grass_blade_culling_desc blade_culling_desc(const std::vector<std::string>& tests) {
    grass_blade_culling_desc c = grass_default_blade_culling_desc();
    for (const std::string& t : tests) {
        if (t == "orientation") c.orientation = 1;
        if (t == "frustum") c.view_frustum = 1;
        if (t == "distance-index") c.distance = GRASS_DISTANCE_CULLING_BLADE_INDEX;
        if (t == "distance-threshold") c.distance = GRASS_DISTANCE_CULLING_THRESHOLD;
    }
    return c;
}

} // namespace grass_sample
