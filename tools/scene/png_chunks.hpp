// A PNG's chunk structure, checked before libpng reads it. libpng 1.6 (its simplified API)
// allocates what an ancillary chunk's length claims before it reads the chunk: a 136-byte
// file whose tEXt chunk claimed 1.95 GB made it allocate 1.95 GB (found by fuzz_png_map).
// A chunk cannot hold more bytes than the file has left, so one that claims more is refused.
#pragma once

#include <cstddef>
#include <string>

namespace grass_sample {

// Empty when every chunk up to IEND (or the end of the bytes) fits in the bytes; otherwise
// which chunk claims how much, and how much is left. Bytes that are not a PNG pass: libpng
// says what is wrong with them.
std::string png_chunk_problem(const unsigned char* bytes, size_t size);

} // namespace grass_sample
