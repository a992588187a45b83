// Scripted input for the viewer (--script): key presses and window sizes at given frames,
// so that tests and screenshots go through the same paths as a user's keys.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace grass_viewer {

struct ScriptStep {
    uint32_t frame = 0; // 1-based: the step happens before this frame is drawn
    int key = 0;        // a GLFW key, or 0 for a resize
    uint32_t width = 0, height = 0;
};

// "FRAME:ACTION,..." with ACTION a key of the viewer (0-5, t, c, m, p, h, b, f2) or size=WxH, e.g.
// "2:m,3:5,4:size=200x120". False and *error naming the step on a bad one.
bool parse_script(const std::string& text, std::vector<ScriptStep>* out, std::string* error);

} // namespace grass_viewer
