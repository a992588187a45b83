#include "animation.hpp"

#include "tool.hpp"

#include <cstdio>
#include <filesystem>
#include <spawn.h>
#include <sys/wait.h>

extern char** environ;

namespace grass_sample {

int run_program(const std::vector<std::string>& args) {
    std::vector<char*> argv;
    for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    pid_t pid = 0;
    if (posix_spawnp(&pid, argv[0], nullptr, nullptr, argv.data(), environ) != 0) return 127;
    int status = 0;
    if (waitpid(pid, &status, 0) != pid) return 127;
    return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

bool Animation::open(const std::string& dir, double fps, std::string* error) {
    dir_ = dir;
    fps_ = fps;
    frames_.clear();
    if (!make_dirs(dir)) {
        *error = "cannot create the directory " + dir;
        return false;
    }
    // The frames of an earlier, longer run would end up in this run's GIF and MP4.
    std::error_code ignored;
    for (const auto& entry : std::filesystem::directory_iterator(dir, ignored)) {
        const std::string name = entry.path().filename().string();
        if (name.size() == 14 && name.compare(0, 6, "frame-") == 0 && name.compare(10, 4, ".png") == 0)
            std::filesystem::remove(entry.path(), ignored);
    }
    return true;
}

std::string Animation::frame_path(size_t index) const {
    char name[32];
    std::snprintf(name, sizeof(name), "/frame-%04zu.png", index);
    return dir_ + name;
}

bool Animation::add(const grass_host::Image& image, std::string* error) {
    const std::string path = frame_path(frames_.size());
    if (!grass_host::write_png(path, image, error)) return false;
    frames_.push_back(path);
    return true;
}

namespace {

bool run(const std::vector<std::string>& args, std::string* error) {
    const int status = run_program(args);
    if (status == 0) return true;
    std::string line;
    for (const std::string& a : args) line += (line.empty() ? "" : " ") + a;
    *error = status == 127 ? args[0] + " is not installed (scripts/install-deps.sh installs it): " + line
                           : line + " exited with " + std::to_string(status);
    return false;
}

} // namespace

bool Animation::finish(std::string* error) {
    if (frames_.empty()) {
        *error = "no frames to make an animation of";
        return false;
    }
    const std::string rate = std::to_string(fps_);
    const std::string input = dir_ + "/frame-%04d.png";
    // GIF: one palette for the whole animation (grass is many greens), ordered dithering
    // (it compresses better than error diffusion and does not crawl from frame to frame).
    if (!run({"ffmpeg", "-v", "error", "-y", "-framerate", rate, "-i", input, "-vf",
              "split[a][b];[a]palettegen=max_colors=128:stats_mode=full[p];[b][p]paletteuse=dither=bayer:bayer_"
              "scale=3",
              "-loop", "0", gif()},
             error)) {
        return false;
    }
    run_program({"gifsicle", "-b", "-O3", gif()}); // optional: smaller, the same frames; 127 when not installed
    // MP4: H.264 in yuv420p (what every player reads), even sizes as the codec wants.
    return run({"ffmpeg", "-v", "error", "-y", "-framerate", rate, "-i", input, "-vf", "pad=ceil(iw/2)*2:ceil(ih/2)*2",
                "-c:v", "libx264", "-pix_fmt", "yuv420p", "-crf", "26", "-movflags", "+faststart", mp4()},
               error);
}

} // namespace grass_sample
