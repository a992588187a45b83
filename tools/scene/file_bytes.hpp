// Reading a whole file the sample tools were given or a scene names: scene files, glTF files
// and the buffers and images they name, PNG design maps. One function for all of them, so
// that none reads a device, a FIFO or a directory, or more bytes than a limit: a density map
// at /dev/zero read until the tool was killed (issue 37).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace grass_sample {

// The most bytes read from one file: a glTF file, a file it names, a PNG map.
constexpr uint64_t kMaxFileBytes = uint64_t(256) << 20;
// The most bytes of a JSON scene file (the largest sample scene is a few KB).
constexpr uint64_t kMaxSceneFileBytes = uint64_t(16) << 20;

// The whole regular file at `path`, at most `max_bytes` of it; false and *error naming the
// path (cut: cut_path) and what is wrong: missing, not a regular file (a directory, a FIFO, a
// device), larger than max_bytes, or unreadable. A FIFO is opened without blocking and then
// refused, so that no writer is waited for.
bool read_file_bytes(const std::string& path, uint64_t max_bytes, std::vector<unsigned char>* out, std::string* error);

// `text` for a message: at most `max` bytes, cut at a UTF-8 character's start and followed
// by "..." when longer (a 64 MB string is not echoed whole).
std::string cut(const std::string& text, size_t max = 80);
// A path for a message: its last 120 bytes after "..." when longer (the file's name is kept).
std::string cut_path(const std::string& path);

} // namespace grass_sample
