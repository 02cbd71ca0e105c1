#include "garden/render/screenshot.h"

#include <cerrno>
#include <cstdio>
#include <cstring>

#include "garden/render/offscreen_target.h"
#include "io/checked_write.h"

// stb's implementation is compiled here, file-local (STB_IMAGE_WRITE_STATIC),
// so it cannot clash with the copy in Debian's libstb that ImGui pulls in;
// its code is not held to our warning flags.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wconversion"
#pragma GCC diagnostic ignored "-Wsign-conversion"
#pragma GCC diagnostic ignored "-Wold-style-cast"
#pragma GCC diagnostic ignored "-Wcast-align"
#pragma GCC diagnostic ignored "-Wdouble-promotion"
#pragma GCC diagnostic ignored "-Wshadow"
#pragma GCC diagnostic ignored "-Wunused-function"
#pragma GCC diagnostic ignored "-Wunused-parameter"
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#pragma GCC diagnostic ignored "-Wimplicit-fallthrough"
#define STB_IMAGE_WRITE_STATIC
#define STB_IMAGE_WRITE_IMPLEMENTATION
#include <stb/stb_image_write.h>
#pragma GCC diagnostic pop

namespace hg::garden {
namespace {

void appendTo(void* context, void* data, int size) {
    if (size > 0) static_cast<std::string*>(context)->append(static_cast<const char*>(data), static_cast<std::size_t>(size));
}

}  // namespace

std::string writePng(const std::string& path, int width, int height, const std::vector<std::uint8_t>& rgba) {
    if (width <= 0 || height <= 0) return "cannot write " + path + ": empty image";
    if (rgba.size() != static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 4)
        return "cannot write " + path + ": pixel buffer does not match " + std::to_string(width) + "x" +
               std::to_string(height) + " RGBA";
    std::string png;
    if (!stbi_write_png_to_func(appendTo, &png, width, height, 4, rgba.data(), width * 4))
        return "cannot write " + path + ": PNG encoding failed";
    return io::writeFileAtomically(path, png, io::WriteSite::Screenshot);
}

std::string writeFramebufferPng(const std::string& path, int width, int height) {
    return writePng(path, width, height, readColorRows(width, height));
}

}  // namespace hg::garden
