// 16-bit greyscale PNG through libpng (see height_png.hpp).
// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/output/height_png.hpp"

#include <png.h>

namespace pupitre {

bool write_gray16_png(const std::vector<uint16_t>& values, int width, int height, std::FILE* out) {
    if (width <= 0 || height <= 0 || values.size() != size_t(width) * size_t(height)) return false;
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
    if (!png) return false;
    png_infop info = png_create_info_struct(png);
    std::vector<png_byte> row(size_t(width) * 2);
    // libpng reports its errors by longjmp; nothing here owns a resource
    // that the jump would leak besides the structs destroyed below.
    if (!info || setjmp(png_jmpbuf(png))) {
        png_destroy_write_struct(&png, &info);
        return false;
    }
    png_init_io(png, out);
    png_set_IHDR(png, info, png_uint_32(width), png_uint_32(height), 16, PNG_COLOR_TYPE_GRAY,
                 PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    png_write_info(png, info);
    for (int j = 0; j < height; ++j) {
        const uint16_t* v = values.data() + size_t(j) * size_t(width);
        for (int i = 0; i < width; ++i) {  // PNG samples are big-endian
            row[size_t(i) * 2] = png_byte(v[i] >> 8);
            row[size_t(i) * 2 + 1] = png_byte(v[i] & 0xff);
        }
        png_write_row(png, row.data());
    }
    png_write_end(png, nullptr);
    png_destroy_write_struct(&png, &info);
    return std::fflush(out) == 0;
}

}  // namespace pupitre
