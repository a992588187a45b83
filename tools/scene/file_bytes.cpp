#include "file_bytes.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

namespace grass_sample {

namespace {

const char* kind_of(mode_t mode) {
    if (S_ISDIR(mode)) return "a directory";
    if (S_ISFIFO(mode)) return "a FIFO";
    if (S_ISCHR(mode)) return "a character device";
    if (S_ISBLK(mode)) return "a block device";
    if (S_ISSOCK(mode)) return "a socket";
    return "a special file";
}

bool refuse(std::string* error, const std::string& text) {
    *error = text;
    return false;
}

} // namespace

std::string cut(const std::string& text, size_t max) {
    if (text.size() <= max) return text;
    size_t end = max;
    while (end > 0 && (static_cast<unsigned char>(text[end]) & 0xC0) == 0x80) --end; // not inside a character
    return text.substr(0, end) + "...";
}

std::string cut_path(const std::string& path) {
    constexpr size_t kKept = 120;
    if (path.size() <= kKept) return path;
    size_t start = path.size() - kKept;
    while (start < path.size() && (static_cast<unsigned char>(path[start]) & 0xC0) == 0x80) ++start;
    return "..." + path.substr(start);
}

bool read_file_bytes(const std::string& path, uint64_t max_bytes, std::vector<unsigned char>* out, std::string* error) {
    const std::string name = cut_path(path);
    struct stat st {};
    if (stat(path.c_str(), &st) != 0) return refuse(error, "cannot open " + name + ": " + std::strerror(errno));
    if (!S_ISREG(st.st_mode)) return refuse(error, name + " is " + kind_of(st.st_mode) + ", not a regular file");
    // O_NONBLOCK: a FIFO put in the file's place after stat does not block the open.
    const int fd = open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
    if (fd < 0) return refuse(error, "cannot open " + name + ": " + std::strerror(errno));
    struct Closer {
        int fd;
        ~Closer() { close(fd); }
    } closer{fd};
    if (fstat(fd, &st) != 0 || !S_ISREG(st.st_mode))
        return refuse(error, name + " is " + kind_of(st.st_mode) + ", not a regular file");
    const uint64_t size = uint64_t(st.st_size);
    if (size > max_bytes) {
        return refuse(error, name + " has " + std::to_string(size) + " bytes; at most " + std::to_string(max_bytes) +
                                 " are read");
    }
    out->assign(size_t(size), 0);
    size_t done = 0;
    while (done < out->size()) {
        const ssize_t n = read(fd, out->data() + done, out->size() - done);
        if (n < 0 && errno == EINTR) continue;
        if (n < 0) return refuse(error, "cannot read " + name + ": " + std::strerror(errno));
        if (n == 0) break; // it shrank: what is there
        done += size_t(n);
    }
    out->resize(done);
    return true;
}

} // namespace grass_sample
