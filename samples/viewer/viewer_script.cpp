#include "viewer_script.hpp"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <cstdio>
#include <sstream>

namespace grass_viewer {

bool parse_script(const std::string& text, std::vector<ScriptStep>* out, std::string* error) {
    std::stringstream steps(text);
    std::string step;
    out->clear();
    while (std::getline(steps, step, ',')) {
        ScriptStep s;
        char action[32] = {0};
        unsigned frame = 0, w = 0, h = 0;
        char tail = 0;
        bool ok = std::sscanf(step.c_str(), "%u:%31s", &frame, action) == 2 && frame >= 1;
        const std::string a = action;
        if (ok && a.size() == 1 && a[0] >= '0' && a[0] <= '5') {
            s.key = GLFW_KEY_0 + (a[0] - '0');
        } else if (ok && a.size() == 1 && std::string("tcmphb").find(a[0]) != std::string::npos) {
            s.key = GLFW_KEY_A + (a[0] - 'a');
        } else if (ok && a == "f2") {
            s.key = GLFW_KEY_F2;
        } else if (ok && std::sscanf(a.c_str(), "size=%ux%u%c", &w, &h, &tail) == 2 && w >= 16 && h >= 16 &&
                   w <= 8192 && h <= 8192) {
            s.width = w;
            s.height = h;
        } else {
            *error = "\"" + step + "\" is not FRAME:KEY (0-5, t, c, m, p, h, b, f2) or FRAME:size=WxH (16..8192 each)";
            return false;
        }
        s.frame = frame;
        out->push_back(s);
    }
    return true;
}

} // namespace grass_viewer
