#include "json_depth.hpp"

namespace grass_sample {

std::string json_depth_problem(const char* text, size_t size, int max_depth, bool comments) {
    int depth = 0;
    for (size_t i = 0; i < size; ++i) {
        const char c = text[i];
        if (c == '"') { // a string: up to its closing quote, past escaped characters
            for (++i; i < size && text[i] != '"'; ++i)
                if (text[i] == '\\') ++i;
        } else if (comments && c == '/' && i + 1 < size && text[i + 1] == '/') {
            while (i < size && text[i] != '\n') ++i;
        } else if (comments && c == '/' && i + 1 < size && text[i + 1] == '*') {
            for (i += 2; i + 1 < size && !(text[i] == '*' && text[i + 1] == '/');) ++i;
            ++i; // the '/'
        } else if (c == '[' || c == '{') {
            if (++depth > max_depth) {
                return "nests arrays and objects deeper than " + std::to_string(max_depth) + " levels (at byte " +
                       std::to_string(i) + ")";
            }
        } else if (c == ']' || c == '}') {
            --depth;
        }
    }
    return "";
}

} // namespace grass_sample
