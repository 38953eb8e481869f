// The contact sheet (contact.png of `ltrender bench`): every render of a run as thumbnails a
// person can read without the page. One row per scene (or figure), labelled at its left; one
// column per path and variant, labelled at its top; each cell the render, under its caption if
// it has one, with its error heatmap under it; the heatmap's scale as a legend at the bottom
// when there is a heatmap. Labels are drawn into the pixels (image/text.h).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "image/image.h"

namespace lt {

struct ContactCell {
  std::filesystem::path image, heatmap;  // empty: nothing there (a blank cell or no heatmap)
  std::string caption;                   // above the image (a figure's value); empty: none
};

struct ContactSheet {
  std::vector<std::string> row_labels;                             // scenes
  std::vector<std::pair<std::string, std::string>> column_labels;  // path, variant
  std::vector<std::vector<ContactCell>> cells;                     // [row][column]
  int thumb_width = 160, thumb_height = 120;
};

// Reads every cell's images (read_image) and lays the sheet out. Prints one warning to stderr
// when there is no font for the labels.
Image draw_contact_sheet(const ContactSheet& sheet);

}  // namespace lt
