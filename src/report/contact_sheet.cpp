#include "report/contact_sheet.h"

#include <algorithm>
#include <cstdio>

#include "image/image_codec.h"
#include "image/text.h"
#include "metrics/heatmap.h"

namespace lt {

namespace {

constexpr int kPad = 4, kLabelSize = 13, kLegendHeight = 48;
constexpr float kInk[3] = {0.05f, 0.05f, 0.05f};
constexpr float kGrey[3] = {0.35f, 0.35f, 0.35f};

void fill_rect(Image& img, int x0, int y0, int w, int h, const float rgb[3]) {
  for (int y = std::max(0, y0); y < std::min(img.height, y0 + h); ++y) {
    for (int x = std::max(0, x0); x < std::min(img.width, x0 + w); ++x) {
      float* d = img.at(x, y);
      d[0] = rgb[0], d[1] = rgb[1], d[2] = rgb[2], d[3] = 1;
    }
  }
}

// The image letterboxed into w x h at ox, oy.
void paste_thumbnail(Image& sheet, const Image& src, int ox, int oy, int w, int h) {
  std::vector<float> px(static_cast<size_t>(w) * h * 4);
  image_codec().fit_letterbox(src.rgba.data(), src.width, src.height, px.data(), w, h);
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      float* d = sheet.at(ox + x, oy + y);
      const float* s = &px[(static_cast<size_t>(y) * w + x) * 4];
      d[0] = s[0], d[1] = s[1], d[2] = s[2], d[3] = 1;
    }
  }
}

// A label that fits `width`: the font shrinks to 9 px, then the text loses its end.
void draw_fitted(Image& img, int x, int y, std::string text, int width, const float rgb[3]) {
  int size = kLabelSize;
  while (size > 9 && text_width(text, size) > width) --size;
  while (text.size() > 2 && text_width(text, size) > width)
    text = text.substr(0, text.size() - 2) + "~";
  draw_text(img, x, y, text, size, rgb);
}

// The legend's layout: its title, the ramp, then two swatches with their words.
constexpr int kRampOffset = 210, kRampWidth = 320, kSwatchGap = 24, kSecondSwatch = 210;
constexpr const char* kLastLegendWord = "NaN/Inf";

// The width the legend takes: a sheet of one column must still hold it.
int legend_width() {
  return kRampOffset + kRampWidth + kSwatchGap + kSecondSwatch + 16 +
         text_width(kLastLegendWord, kLabelSize) + 2 * kPad;
}

// The heatmap's ramp with its marks in LSB, and the two colours outside the ramp.
void draw_legend(Image& img, int x, int y) {
  const int ramp_width = kRampWidth, ramp_height = 12;
  draw_text(img, x, y, "error heatmap, LSB of 8 bits:", kLabelSize, kInk);
  const int rx = x + kRampOffset;
  for (int i = 0; i < ramp_width; ++i) {
    float rgb[3];
    heatmap_colour(kHeatmapMaxLsb * i / (ramp_width - 1), kHeatmapMaxLsb, rgb);
    fill_rect(img, rx + i, y + 2, 1, ramp_height, rgb);
  }
  for (double v : {0.0, 1.0, 2.0, 4.0, 8.0}) {
    const int tx = rx + static_cast<int>(v / kHeatmapMaxLsb * (ramp_width - 1));
    fill_rect(img, tx, y + 2 + ramp_height, 1, 4, kInk);
    char label[16];
    std::snprintf(label, sizeof label, v == kHeatmapMaxLsb ? "%g+" : "%g", v);
    draw_text(img, tx - 3, y + 20, label, 11, kInk);
  }
  const int sx = rx + ramp_width + kSwatchGap;
  fill_rect(img, sx, y + 2, 12, 12, kHeatmapUncovered);
  draw_text(img, sx + 16, y, "background within 0.5 LSB", kLabelSize, kInk);
  fill_rect(img, sx + kSecondSwatch, y + 2, 12, 12, kHeatmapNonFinite);
  draw_text(img, sx + kSecondSwatch + 16, y, kLastLegendWord, kLabelSize, kInk);
}

}  // namespace

Image draw_contact_sheet(const ContactSheet& s) {
  if (label_font().empty()) {
    std::fprintf(stderr,
                 "ltrender: warning: no DejaVuSans.ttf (Debian: fonts-dejavu-core): the contact "
                 "sheet has no labels\n");
  }
  const int tw = s.thumb_width, th = s.thumb_height;
  bool captions = false, heatmaps = false;
  for (const auto& row : s.cells) {
    for (const ContactCell& cell : row) {
      captions = captions || !cell.caption.empty();
      heatmaps = heatmaps || !cell.heatmap.empty();
    }
  }
  // A cell: its caption, the render, and the heatmap under it, each only where the sheet has one.
  const int caption_height = captions ? kPad + kLabelSize + 4 : 0;
  const int heatmap_height = heatmaps ? th + kPad : 0;
  const int cell_height = caption_height + th + heatmap_height + 2 * kPad;
  int label_column = 0;
  for (const std::string& r : s.row_labels)
    label_column = std::max(label_column, text_width(r, kLabelSize));
  label_column = std::min(label_column, 240) + 2 * kPad;
  const int header = 2 * (kLabelSize + 4) + kPad;
  const int cols = static_cast<int>(s.column_labels.size());
  const int rows = static_cast<int>(s.row_labels.size());
  const int grid_width = label_column + cols * (tw + kPad) + kPad;
  Image sheet(heatmaps ? std::max(grid_width, legend_width()) : grid_width,
              header + rows * cell_height + (heatmaps ? kLegendHeight : kPad));
  const float white[3] = {1, 1, 1};
  fill_rect(sheet, 0, 0, sheet.width, sheet.height, white);
  for (int c = 0; c < cols; ++c) {
    const int x = label_column + c * (tw + kPad);
    draw_fitted(sheet, x, kPad, s.column_labels[c].first, tw, kInk);
    draw_fitted(sheet, x, kPad + kLabelSize + 4, s.column_labels[c].second, tw, kGrey);
  }
  for (int r = 0; r < rows; ++r) {
    const int y = header + r * cell_height;
    // The row label beside the middle of the render(s) and heatmap(s).
    const int middle = y + caption_height + (th + heatmap_height) / 2;
    draw_fitted(sheet, kPad, middle - kLabelSize / 2, s.row_labels[r], label_column - 2 * kPad,
                kInk);
    for (int c = 0; c < cols && c < static_cast<int>(s.cells[r].size()); ++c) {
      const ContactCell& cell = s.cells[r][c];
      const int x = label_column + c * (tw + kPad);
      if (!cell.caption.empty()) draw_fitted(sheet, x, y + kPad, cell.caption, tw, kInk);
      const int image_y = y + caption_height;
      if (!cell.image.empty()) paste_thumbnail(sheet, read_image(cell.image), x, image_y, tw, th);
      if (!cell.heatmap.empty())
        paste_thumbnail(sheet, read_image(cell.heatmap), x, image_y + th + kPad, tw, th);
    }
  }
  if (heatmaps) draw_legend(sheet, kPad, header + rows * cell_height + kPad);
  return sheet;
}

}  // namespace lt
