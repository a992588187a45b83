#include "png_palette.hpp"

#include <png.h>

#include <csetjmp>
#include <cstring>
#include <vector>

namespace grass_sample {

namespace {

struct Source {
    const unsigned char* bytes;
    size_t size, at;
};

void read_bytes(png_structp png, png_bytep out, png_size_t n) {
    Source* s = static_cast<Source*>(png_get_io_ptr(png));
    if (n > s->size - s->at) png_error(png, "the file ends early");
    std::memcpy(out, s->bytes + s->at, n);
    s->at += n;
}

void quiet(png_structp, png_const_charp) {}

// Reads the image and names its first index past the palette into `problem`. libpng's errors
// longjmp out of it to png_palette_problem's setjmp: it holds nothing that needs destroying
// while a libpng call runs (what it fills is the caller's), and the setjmp frame constructs no
// string (GCC's -Wclobbered, at -O1, flags std::string's own locals there).
[[gnu::noinline]] void find_index_past_palette(png_structp png, png_infop info, std::vector<png_byte>& pixels,
                                               std::vector<png_bytep>& rows, std::string& problem) {
    png_read_info(png, info);
    png_colorp palette = nullptr;
    int colours = 0;
    if (png_get_color_type(png, info) != PNG_COLOR_TYPE_PALETTE ||
        png_get_PLTE(png, info, &palette, &colours) != PNG_INFO_PLTE)
        return;
    png_set_packing(png); // 1, 2 and 4-bit indices a byte each
    png_set_interlace_handling(png);
    png_read_update_info(png, info);
    const png_uint_32 width = png_get_image_width(png, info), height = png_get_image_height(png, info);
    pixels.resize(size_t(width) * height);
    rows.resize(height);
    for (png_uint_32 y = 0; y < height; ++y) rows[y] = pixels.data() + size_t(y) * width;
    png_read_image(png, rows.data());
    for (size_t k = 0; k < pixels.size() && problem.empty(); ++k) {
        if (pixels[k] < colours) continue;
        problem = "pixel (" + std::to_string(k % width) + ", " + std::to_string(k / width) + ") has palette index " +
                  std::to_string(pixels[k]) + "; the palette has " + std::to_string(colours) + " colours";
    }
}

} // namespace

std::string png_palette_problem(const unsigned char* bytes, size_t size) {
    if (size < 8 || png_sig_cmp(bytes, 0, 8) != 0) return "";
    png_structp png = png_create_read_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, &quiet);
    if (!png) return "";
    png_infop info = png_create_info_struct(png);
    Source source{bytes, size, 0};
    std::vector<png_byte> pixels;
    std::vector<png_bytep> rows;
    std::string problem;
    if (info && setjmp(png_jmpbuf(png)) == 0) {
        png_set_read_fn(png, &source, &read_bytes);
        find_index_past_palette(png, info, pixels, rows, problem);
    }
    png_destroy_read_struct(&png, info ? &info : nullptr, nullptr);
    return problem;
}

} // namespace grass_sample
