// Storage for a framebuffer's colour and depth renderbuffers, attached and checked.
#pragma once

namespace pool::render {

/// Gives the bound framebuffer `colour` (RGBA8) and `depth` (24-bit) renderbuffers of width ×
/// height, `samples` a pixel when over 1 (at most what the driver allows), and attaches them;
/// throws std::runtime_error when the framebuffer is incomplete.
void attachColourAndDepth(unsigned colour, unsigned depth, int width, int height, int samples = 0);

}  // namespace pool::render
