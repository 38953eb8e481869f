// Text drawn into an image's pixels (the contact sheet's labels and legend), through
// OpenImageIO's render_text (FreeType) with DejaVu Sans from Debian's fonts-dejavu-core
// (scripts/setup.sh installs it).
#pragma once

#include <filesystem>
#include <string>

#include "image/image.h"

namespace lt {

// The font file, or empty when none of the places it is installed holds it.
const std::filesystem::path& label_font();

// Draws `text` with its top-left corner at x, y, `size` pixels high, in linear RGB `rgb`.
// Returns false (and draws nothing) without the font; the caller says so once.
bool draw_text(Image& image, int x, int y, const std::string& text, int size, const float rgb[3]);

// The width in pixels `text` takes at `size` (an estimate of 0.6 size a character without the
// font).
int text_width(const std::string& text, int size);

}  // namespace lt
