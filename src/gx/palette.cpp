// Median-cut palettes for the colour-indexed formats (palette.h).
#include "gx/palette.h"

#include <algorithm>
#include <array>
#include <limits>

#include "core/error.h"
#include "gx/texture_decoder.h"

namespace lt::gx {

u16 encode_tlut_entry(const Color8& c, TlutFormat format, Rounding rounding) {
  switch (format) {
    case TlutFormat::IA8:
      return static_cast<u16>(c.a << 8 | intensity_of(c, rounding));
    case TlutFormat::RGB565:
      return encode_rgb565(c, rounding);
    case TlutFormat::RGB5A3:
      return encode_rgb5a3(c, rounding, c.a == 255);
  }
  LT_CHECK(false, "not a GX TLUT format");
  return 0;
}

namespace {

// A box of median cut: a range of `order` (texel numbers) and its longest side.
struct MedianCutBox {
  size_t begin = 0, end = 0;
  int channel = 0, extent = 0;  // the channel with the largest max - min, and that difference
};

void measure_box(MedianCutBox& box, const std::vector<int>& order,
                 const std::vector<Color8>& texels) {
  std::array<int, 4> lo{255, 255, 255, 255}, hi{0, 0, 0, 0};
  for (size_t k = box.begin; k < box.end; ++k) {
    const Color8& c = texels[static_cast<size_t>(order[k])];
    for (int ch = 0; ch < 4; ++ch) {
      lo[ch] = std::min(lo[ch], int{c[ch]});
      hi[ch] = std::max(hi[ch], int{c[ch]});
    }
  }
  box.extent = -1;
  for (int ch = 0; ch < 4; ++ch)
    if (hi[ch] - lo[ch] > box.extent) {
      box.extent = hi[ch] - lo[ch];
      box.channel = ch;
    }
}

Color8 mean_colour(const MedianCutBox& box, const std::vector<int>& order,
                   const std::vector<Color8>& texels) {
  std::array<long long, 4> sum{};
  for (size_t k = box.begin; k < box.end; ++k)
    for (int ch = 0; ch < 4; ++ch) sum[ch] += texels[static_cast<size_t>(order[k])][ch];
  const long long n = static_cast<long long>(box.end - box.begin);
  Color8 c;
  for (int ch = 0; ch < 4; ++ch) c[ch] = static_cast<u8>((sum[ch] * 2 + n) / (2 * n));
  return c;
}

int distance2(const Color8& a, const Color8& b) {
  int d = 0;
  for (int ch = 0; ch < 4; ++ch) d += (a[ch] - b[ch]) * (a[ch] - b[ch]);
  return d;
}

}  // namespace

Palette make_palette(const Rgba8Image& image, int max_entries, TlutFormat format,
                     Rounding rounding) {
  LT_CHECK(max_entries >= 1 && !image.texels.empty(), "a palette of at least one entry");
  const std::vector<Color8>& texels = image.texels;
  std::vector<int> order(texels.size());
  for (size_t k = 0; k < order.size(); ++k) order[k] = static_cast<int>(k);
  std::vector<MedianCutBox> boxes{{0, order.size(), 0, 0}};
  measure_box(boxes[0], order, texels);
  while (static_cast<int>(boxes.size()) < max_entries) {
    // The box with the longest side (the first such); none splittable when all are one colour.
    auto widest = std::max_element(
        boxes.begin(), boxes.end(),
        [](const MedianCutBox& a, const MedianCutBox& b) { return a.extent < b.extent; });
    if (widest->extent <= 0) break;
    MedianCutBox& box = *widest;
    const int ch = box.channel;
    const auto first = order.begin() + static_cast<std::ptrdiff_t>(box.begin);
    const auto last = order.begin() + static_cast<std::ptrdiff_t>(box.end);
    std::sort(first, last, [&](int a, int b) {
      return texels[static_cast<size_t>(a)][ch] < texels[static_cast<size_t>(b)][ch];
    });
    // Split at the median, moved off a run of equal values so both halves are non-empty and
    // differ in this channel (the box's extent > 0 guarantees a place to cut).
    size_t cut = box.begin + (box.end - box.begin) / 2;
    const auto value = [&](size_t k) { return texels[static_cast<size_t>(order[k])][ch]; };
    while (cut > box.begin && value(cut - 1) == value(cut)) --cut;
    if (cut == box.begin)
      while (cut < box.end && value(cut) == value(box.begin)) ++cut;
    MedianCutBox upper{cut, box.end, 0, 0};
    box.end = cut;
    measure_box(box, order, texels);
    measure_box(upper, order, texels);
    boxes.push_back(upper);
  }
  Palette palette;
  palette.indices.assign(texels.size(), 0);
  std::vector<Color8> decoded;
  for (size_t b = 0; b < boxes.size(); ++b) {
    const u16 entry = encode_tlut_entry(mean_colour(boxes[b], order, texels), format, rounding);
    palette.entries.push_back(entry);
    decoded.push_back(
        decode_tlut_entry(format, static_cast<u8>(entry >> 8), static_cast<u8>(entry)));
    for (size_t k = boxes[b].begin; k < boxes[b].end; ++k)
      palette.indices[static_cast<size_t>(order[k])] = static_cast<int>(b);
  }
  if (max_entries > 256) return palette;  // CI14X2: each texel keeps its box's entry
  for (size_t t = 0; t < texels.size(); ++t) {
    int best = 0, best_d = std::numeric_limits<int>::max();
    for (size_t e = 0; e < decoded.size(); ++e) {
      const int d = distance2(texels[t], decoded[e]);
      if (d < best_d) {
        best_d = d;
        best = static_cast<int>(e);
      }
    }
    palette.indices[t] = best;
  }
  return palette;
}

}  // namespace lt::gx
