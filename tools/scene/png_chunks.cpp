#include "png_chunks.hpp"

#include <cstdint>
#include <cstring>

namespace grass_sample {

std::string png_chunk_problem(const unsigned char* bytes, size_t size) {
    static const unsigned char kSignature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
    if (size < 8 || std::memcmp(bytes, kSignature, 8) != 0) return "";
    size_t offset = 8;
    while (size - offset >= 8) {
        const uint32_t length = (uint32_t(bytes[offset]) << 24) | (uint32_t(bytes[offset + 1]) << 16) |
                                (uint32_t(bytes[offset + 2]) << 8) | uint32_t(bytes[offset + 3]);
        const std::string type(reinterpret_cast<const char*>(bytes + offset + 4), 4);
        const size_t left = size - offset - 8; // after the length and type
        if (uint64_t(length) + 4 > left) {     // the data and its CRC
            bool printable = true;
            for (char c : type) printable = printable && ((c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z'));
            return "its chunk " + (printable ? "\"" + type + "\"" : std::string("(unnamed)")) + " at byte " +
                   std::to_string(offset) + " claims " + std::to_string(length) + " bytes; the file has " +
                   std::to_string(left) + " left";
        }
        if (type == "IEND") break;
        offset += 12 + size_t(length);
    }
    return "";
}

} // namespace grass_sample
