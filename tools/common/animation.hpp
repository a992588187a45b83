// An animation of rendered frames (grass-render --animation DIR): the frames as PNGs
// (DIR/frame-0000.png, ...), then an animated GIF (DIR/animation.gif, made smaller by gifsicle
// when it is installed) and an H.264 MP4 (DIR/animation.mp4), both made by ffmpeg.
#pragma once

#include "image_io.hpp"

#include <string>
#include <vector>

namespace grass_sample {

class Animation {
public:
    // Creates `dir` (as mkdir -p); false and *error when it cannot.
    bool open(const std::string& dir, double fps, std::string* error);
    // Writes the next frame's PNG.
    bool add(const grass_host::Image& image, std::string* error);
    // Makes the GIF and the MP4 from the frames written; false and *error (the tool's
    // command line and its exit status) when ffmpeg is missing or fails.
    bool finish(std::string* error);

    const std::vector<std::string>& frames() const { return frames_; }
    std::string gif() const { return dir_ + "/animation.gif"; }
    std::string mp4() const { return dir_ + "/animation.mp4"; }

private:
    std::string frame_path(size_t index) const;

    std::string dir_;
    double fps_ = 24.0;
    std::vector<std::string> frames_;
};

// Runs a program found on PATH with these arguments (no shell), its output on ours. Its exit
// status; 127 when it cannot be started.
int run_program(const std::vector<std::string>& args);

} // namespace grass_sample
