// Screenshots as PNG files (F12 in the desktop garden, `replay
// --screenshots`). Files appear whole or not at all: they are written to a
// temporary name beside the target and renamed.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace hg::garden {

// `rgba`: width * height * 4 bytes, rows top-down. "" on success, otherwise
// a message naming the path and the system's reason.
std::string writePng(const std::string& path, int width, int height, const std::vector<std::uint8_t>& rgba);

// Reads the bound read framebuffer (the window's back buffer before the
// swap, or a bound OffscreenTarget) and writes it as a PNG.
std::string writeFramebufferPng(const std::string& path, int width, int height);

}  // namespace hg::garden
