// SPDX-License-Identifier: LGPL-3.0-or-later
// PNG via libpng. libpng reports errors by longjmp: every function calling setjmp below keeps
// only trivially destructible locals (pointers), and the callbacks never let a C++ exception
// cross libpng; error text is stored in a context struct and turned into an exception after
// libpng has been torn down.
#include <exbsp/view/png_io.h>

#include <png.h>

#include <cerrno>
#include <csetjmp>
#include <cstdlib>
#include <cstdio>
#include <cstring>
#include <string_view>

#include <exbsp/core/errors.h>
#include "core/atomic_file.h"

namespace exbsp::view {

namespace {

struct png_context {
  std::vector<std::uint8_t>* out = nullptr;
  char message[256] = "libpng error";
};

void on_error(png_structp png, png_const_charp msg) {
  auto* ctx = static_cast<png_context*>(png_get_error_ptr(png));
  std::snprintf(ctx->message, sizeof ctx->message, "%s", msg ? msg : "libpng error");
  std::longjmp(png_jmpbuf(png), 1);
}

void on_warning(png_structp, png_const_charp) {}

void on_write(png_structp png, png_bytep data, png_size_t n) {
  auto* ctx = static_cast<png_context*>(png_get_io_ptr(png));
  bool ok = true;
  try {
    ctx->out->insert(ctx->out->end(), data, data + n);
  } catch (...) {
    ok = false;
  }
  if (!ok) png_error(png, "out of memory");
}

void on_flush(png_structp) {}

// Returns true on success. Only pointers live across setjmp.
bool encode_rows(png_context* ctx, int width, int height, png_bytepp rows) {
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, ctx, on_error, on_warning);
  if (!png) return false;
  png_infop info = png_create_info_struct(png);
  if (!info) {
    png_destroy_write_struct(&png, nullptr);
    return false;
  }
  if (setjmp(png_jmpbuf(png))) {
    png_destroy_write_struct(&png, &info);
    return false;
  }
  png_set_write_fn(png, ctx, on_write, on_flush);
  png_set_IHDR(png, info, static_cast<png_uint_32>(width), static_cast<png_uint_32>(height), 8,
               PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT,
               PNG_FILTER_TYPE_DEFAULT);
  png_write_info(png, info);
  png_write_image(png, rows);
  png_write_end(png, info);
  png_destroy_write_struct(&png, &info);
  return true;
}

struct read_source {
  const std::uint8_t* data;
  std::size_t size, pos;
};

void on_read(png_structp png, png_bytep out, png_size_t n) {
  auto* src = static_cast<read_source*>(png_get_io_ptr(png));
  if (src->size - src->pos < n) png_error(png, "unexpected end of file");
  std::memcpy(out, src->data + src->pos, n);
  src->pos += n;
}

// Buffers of a decode, owned by the caller so that their values survive a longjmp.
struct decode_buffers {
  std::uint8_t* pixels = nullptr;
  png_bytepp rows = nullptr;
  int width = 0, height = 0;
};

// Decodes into out->pixels (malloc'd, 3 bytes per pixel, top row first; the caller frees it).
// Returns false on error (out->pixels is then null).
bool decode_rows(png_context* ctx, read_source* src, decode_buffers* out) {
  png_structp png = png_create_read_struct(PNG_LIBPNG_VER_STRING, ctx, on_error, on_warning);
  if (!png) return false;
  png_infop info = png_create_info_struct(png);
  if (!info) {
    png_destroy_read_struct(&png, nullptr, nullptr);
    return false;
  }
  if (setjmp(png_jmpbuf(png))) {
    std::free(out->rows);
    std::free(out->pixels);
    out->rows = nullptr;
    out->pixels = nullptr;
    png_destroy_read_struct(&png, &info, nullptr);
    return false;
  }
  png_set_read_fn(png, src, on_read);
  png_read_info(png, info);
  const png_uint_32 w = png_get_image_width(png, info), h = png_get_image_height(png, info);
  if (w == 0 || h == 0 || w > 65536 || h > 65536) png_error(png, "image size out of range");
  const int color_type = png_get_color_type(png, info);
  if (png_get_bit_depth(png, info) == 16) png_set_strip_16(png);
  if (color_type == PNG_COLOR_TYPE_PALETTE) png_set_palette_to_rgb(png);
  if (color_type == PNG_COLOR_TYPE_GRAY || color_type == PNG_COLOR_TYPE_GRAY_ALPHA)
    png_set_gray_to_rgb(png);
  if (png_get_bit_depth(png, info) < 8) png_set_expand(png);
  if (png_get_valid(png, info, PNG_INFO_tRNS)) png_set_tRNS_to_alpha(png);
  png_set_strip_alpha(png);
  png_set_interlace_handling(png);
  png_read_update_info(png, info);
  if (png_get_rowbytes(png, info) != 3 * static_cast<std::size_t>(w))
    png_error(png, "unsupported pixel format");
  out->pixels = static_cast<std::uint8_t*>(std::malloc(3 * static_cast<std::size_t>(w) * h));
  out->rows = static_cast<png_bytepp>(std::malloc(sizeof(png_bytep) * h));
  if (!out->pixels || !out->rows) png_error(png, "out of memory");
  for (png_uint_32 r = 0; r < h; ++r)
    out->rows[r] = out->pixels + 3 * static_cast<std::size_t>(w) * r;
  png_read_image(png, out->rows);
  png_read_end(png, nullptr);
  std::free(out->rows);
  out->rows = nullptr;
  png_destroy_read_struct(&png, &info, nullptr);
  out->width = static_cast<int>(w);
  out->height = static_cast<int>(h);
  return true;
}

}  // namespace

std::vector<std::uint8_t> encode_png(const image& img) {
  std::vector<std::uint8_t> out;
  std::vector<png_bytep> rows(static_cast<std::size_t>(img.height()));
  auto* base = const_cast<std::uint8_t*>(img.data().data());
  for (int r = 0; r < img.height(); ++r)
    rows[r] = base + 3 * static_cast<std::size_t>(img.width()) * r;
  png_context ctx;
  ctx.out = &out;
  if (!encode_rows(&ctx, img.width(), img.height(), rows.data()))
    throw usage_error(std::string("PNG encoding failed: ") + ctx.message);
  return out;
}

void write_png(const image& img, const std::string& path) {
  const std::vector<std::uint8_t> bytes = encode_png(img);
  write_file_atomically(
      path, std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()));
}

image read_png(const std::string& path) {
  std::FILE* f = std::fopen(path.c_str(), "rb");
  if (!f) throw input_error(path, 0, std::string("cannot open: ") + std::strerror(errno));
  std::vector<std::uint8_t> bytes;
  std::uint8_t chunk[65536];
  std::size_t n;
  while ((n = std::fread(chunk, 1, sizeof chunk, f)) > 0)
    bytes.insert(bytes.end(), chunk, chunk + n);
  const bool read_error = std::ferror(f) != 0;
  std::fclose(f);
  if (read_error) throw input_error(path, 0, "read error");
  if (bytes.size() < 8 || png_sig_cmp(bytes.data(), 0, 8) != 0)
    throw input_error(path, 0, "not a PNG file");
  read_source src{bytes.data(), bytes.size(), 0};
  png_context ctx;
  decode_buffers buf;
  if (!decode_rows(&ctx, &src, &buf))
    throw input_error(path, 0, std::string("invalid PNG: ") + ctx.message);
  image img;
  try {
    img = image(buf.width, buf.height, rgb8{});
  } catch (...) {
    std::free(buf.pixels);
    throw;
  }
  std::memcpy(img.data().data(), buf.pixels, img.data().size());
  std::free(buf.pixels);
  return img;
}

}  // namespace exbsp::view
