#include "tool.hpp"

#include <cerrno>
#include <cstdio>
#include <sstream>
#include <sys/stat.h>

namespace grass_sample {

void check(grass_result result, const char* call, const grass_context* ctx) {
    if (result == GRASS_SUCCESS) return;
    std::string message = std::string(call) + " failed: " + grass_result_string(result);
    const char* last = ctx ? grass_get_last_error(ctx) : nullptr;
    if (last && *last) message += std::string(" (") + last + ")";
    throw Failure(message);
}

int fail(const char* tool, const std::string& message) {
    std::fprintf(stderr, "%s: %s\n", tool, message.c_str());
    return 1;
}

void GRASS_API_PTR log_to_stderr(void*, grass_log_level level, grass_message_id id, const char* message) {
    static const char* const names[] = {"error", "warning", "info"};
    std::fprintf(stderr, "grass %s %d: %s\n", names[level], static_cast<int>(id), message);
}

bool make_dirs(const std::string& path) {
    std::string partial;
    std::stringstream ss(path);
    std::string part;
    if (!path.empty() && path[0] == '/') partial = "/";
    while (std::getline(ss, part, '/')) {
        if (part.empty()) continue;
        partial += part + "/";
        if (mkdir(partial.c_str(), 0755) != 0 && errno != EEXIST) return false;
    }
    return true;
}

bool write_text(const std::string& path, const std::string& text) {
    FILE* f = std::fopen(path.c_str(), "wb");
    if (!f) return false;
    const bool ok = std::fwrite(text.data(), 1, text.size(), f) == text.size();
    return std::fclose(f) == 0 && ok;
}

} // namespace grass_sample
