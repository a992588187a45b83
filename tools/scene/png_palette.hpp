// A palette PNG's indices, checked against its palette. libpng's simplified API reads an
// index past the palette as black without a warning: a density map whose indices ran past
// its two colours gave zero density where the file meant something (issue 37).
#pragma once

#include <cstddef>
#include <string>

namespace grass_sample {

// Empty for a PNG that has no palette or whose every index lies in its palette; otherwise
// the first pixel whose index does not ("pixel (3, 0) has palette index 5; the palette has
// 2 colours"). Bytes libpng cannot read pass: the caller's decode says what is wrong. The
// caller checks the image's size first (it decodes the indices: a byte a pixel).
std::string png_palette_problem(const unsigned char* bytes, size_t size);

} // namespace grass_sample
