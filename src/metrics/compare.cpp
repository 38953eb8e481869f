#include "metrics/compare.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>

#include "core/error.h"
#include "core/fixed.h"

namespace lt {

namespace {

constexpr const char* kChannelNames[3] = {"R", "G", "B"};

double clamp01(double v) {
  return std::clamp(v, 0.0, 1.0);
}

// Accumulates one region's figures in one pass over the pixels; the percentile needs every
// per-pixel error, so those are kept.
class RegionAccumulator {
 public:
  void add(int x, int y, const double e[3]) {
    double worst = 0.0;
    for (int c = 0; c < 3; ++c) {
      sum_ += e[c];
      sum_sq_ += e[c] * e[c];
      // Strictly greater: the first pixel in reading order (top-left first, R first) wins ties,
      // and a region without error keeps no location (max_lsb starts at 0).
      if (e[c] > stats_.max_lsb) {
        stats_.max_lsb = e[c];
        stats_.max_x = x, stats_.max_y = y, stats_.max_channel = c;
      }
      worst = std::max(worst, e[c]);
    }
    pixel_errors_.push_back(worst);
    if (worst > 1.0) ++over_1_;
    if (worst > 4.0) ++over_4_;
  }

  ErrorStats finish() {
    const size_t n = pixel_errors_.size();
    stats_.pixels = n;
    if (n == 0) return stats_;  // empty region: zeros, PSNR inf, max at -1,-1
    const double values = 3.0 * static_cast<double>(n);
    stats_.mean_lsb = sum_ / values;
    stats_.rmse_lsb = std::sqrt(sum_sq_ / values);
    // Peak 1.0 = 255 LSB: PSNR = 10 log10(1 / MSE) with MSE in [0, 1] units.
    stats_.psnr_db = stats_.rmse_lsb > 0.0 ? 20.0 * std::log10(255.0 / stats_.rmse_lsb)
                                           : std::numeric_limits<double>::infinity();
    // Nearest rank: the smallest error that at least 99% of pixels are at or under. Integer
    // ceil(0.99 n) so that n = 100 gives rank 99, not 100 through 0.99's rounding.
    const size_t rank = (99 * n + 99) / 100;
    std::nth_element(pixel_errors_.begin(), pixel_errors_.begin() + (rank - 1),
                     pixel_errors_.end());
    stats_.p99_lsb = pixel_errors_[rank - 1];
    stats_.percent_over_1_lsb = 100.0 * static_cast<double>(over_1_) / static_cast<double>(n);
    stats_.percent_over_4_lsb = 100.0 * static_cast<double>(over_4_) / static_cast<double>(n);
    return stats_;
  }

 private:
  ErrorStats stats_;
  double sum_ = 0.0, sum_sq_ = 0.0;
  size_t over_1_ = 0, over_4_ = 0;
  std::vector<double> pixel_errors_;
};

std::string size_string(const Image& image) {
  return std::to_string(image.width) + "x" + std::to_string(image.height);
}

bool pixel_is_finite(const float* p) {
  return std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]) && std::isfinite(p[3]);
}

const ErrorStats& region_stats(const Comparison& comparison, Region region) {
  return region == Region::kCovered ? comparison.covered : comparison.image;
}

// JSON has no infinity; null says "no finite value" without looking like a measurement.
nlohmann::ordered_json number_or_null(double v) {
  return std::isfinite(v) ? nlohmann::ordered_json(v) : nlohmann::ordered_json(nullptr);
}

nlohmann::ordered_json stats_to_json(const ErrorStats& s) {
  nlohmann::ordered_json max_at = nullptr;
  if (s.max_channel >= 0) {
    max_at = {{"x", s.max_x}, {"y", s.max_y}, {"channel", kChannelNames[s.max_channel]}};
  }
  return {
      {"pixels", s.pixels},
      {"max_lsb", s.max_lsb},
      {"max_at", max_at},
      {"mean_lsb", s.mean_lsb},
      {"rmse_lsb", s.rmse_lsb},
      {"psnr_db", number_or_null(s.psnr_db)},
      {"p99_lsb", s.p99_lsb},
      {"percent_over_1_lsb", s.percent_over_1_lsb},
      {"percent_over_4_lsb", s.percent_over_4_lsb},
  };
}

std::string format(const char* fmt, double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, fmt, v);
  return buf;
}

std::string lsb_string(double v) {
  return std::isfinite(v) ? fixed(v, 3) : "inf";
}

std::string location_string(const ErrorStats& s) {
  if (s.max_channel < 0) return "-";
  return std::to_string(s.max_x) + "," + std::to_string(s.max_y) + " " +
         kChannelNames[s.max_channel];
}

// Half an LSB: the floor of an 8-bit image against a float one. A pixel at or under it is no
// edge and no shade, so its shift error is its error (and the neighbourhoods of the nearly every
// pixel of a bench comparison need not be searched).
constexpr double kShiftFloorLsb = 0.5;

// A value as the error formula of metrics.md sees it, in LSB: an 8-bit value as its byte, a
// float one as 255 x its clamped value (channel_error_lsb is the difference of two of these).
double lsb_value(float v, TestEncoding encoding) {
  return encoding == TestEncoding::kUnorm8 ? static_cast<double>(to_unorm8(v)) : clamp01(v) * 255.0;
}

// How far `value` (LSB) lies outside what `image` spans in the 3x3 neighbourhood of x, y, at its
// worst channel: 0 when each channel is near its neighbours' range. A range, not one neighbour's
// value: a silhouette moved by a fraction of a pixel leaves a value between its neighbours'
// (coverage and the shading's interpolation). Widened by half its own width: a pixel a moved
// silhouette newly covers takes a shade no neighbour had (a sphere's grazing rim is its
// brightest), but only where the neighbourhood holds an edge; a flat one is not widened at all,
// so a 2 LSB change in a flat interior stays shading. A neighbour off the image, or not
// finite, is no candidate: a shape at the border does not wrap round.
double outside_neighbourhood(const float* value, TestEncoding value_encoding, const Image& image,
                             TestEncoding image_encoding, int x, int y) {
  // Each neighbour's finiteness and LSB values once for its three channels (the bench's and the
  // bounds tests' comparisons spend their time here); a channel still meets its neighbours in
  // row order, so every min and max is the one a channel-by-channel scan gives.
  double lo[3], hi[3];
  for (int c = 0; c < 3; ++c) {
    lo[c] = std::numeric_limits<double>::infinity();
    hi[c] = -lo[c];
  }
  for (int ny = std::max(0, y - 1); ny <= std::min(image.height - 1, y + 1); ++ny) {
    for (int nx = std::max(0, x - 1); nx <= std::min(image.width - 1, x + 1); ++nx) {
      const float* q = image.at(nx, ny);
      if (!pixel_is_finite(q)) continue;
      for (int c = 0; c < 3; ++c) {
        const double v = lsb_value(q[c], image_encoding);
        lo[c] = std::min(lo[c], v);
        hi[c] = std::max(hi[c], v);
      }
    }
  }
  double worst = 0.0;
  for (int c = 0; c < 3; ++c) {
    const double widen = (hi[c] - lo[c]) / 2.0;
    const double l = lo[c] - widen, h = hi[c] + widen;
    const double v = lsb_value(value[c], value_encoding);
    worst = std::max(worst, v < l ? l - v : v > h ? v - h : 0.0);
  }
  return worst;
}

// Comparison::pixel_shift_error_lsb: for each pixel over the floor, how far the test's value is
// outside what the reference spans around it, and the reference's outside what the test spans,
// the larger of the two (one way is not enough: a line removed from the test leaves background
// that the reference has beside the line, but the line is nowhere in the test).
void fill_shift_errors(const Image& test, const Image& reference, TestEncoding encoding,
                       TestEncoding reference_encoding, Comparison& out) {
  out.pixel_shift_error_lsb = out.pixel_error_lsb;
  for (int y = 0; y < test.height; ++y) {
    for (int x = 0; x < test.width; ++x) {
      const size_t i = static_cast<size_t>(y) * test.width + x;
      if (!(out.pixel_error_lsb[i] > kShiftFloorLsb)) continue;  // NaN stays NaN
      const double forward =
          outside_neighbourhood(test.at(x, y), encoding, reference, reference_encoding, x, y);
      const double backward =
          outside_neighbourhood(reference.at(x, y), reference_encoding, test, encoding, x, y);
      out.pixel_shift_error_lsb[i] = std::min(out.pixel_error_lsb[i], std::max(forward, backward));
    }
  }
}

}  // namespace

double channel_error_lsb(float test, float reference, TestEncoding encoding,
                         TestEncoding reference_encoding) {
  if (reference_encoding == TestEncoding::kUnorm8) {
    // An 8-bit reference (a golden) holds k/255, which a float only approximates: float(k/255)
    // * 255 is k give or take 8e-6, enough to print a PSNR of 159 dB for two identical files and
    // to count a 1 LSB step as more than 1 LSB. to_unorm8 gives back its byte k exactly, the
    // value metrics.md's formula means (and k/255 is in [0, 1] already).
    const double k = to_unorm8(reference);
    return encoding == TestEncoding::kUnorm8 ? std::abs(to_unorm8(test) - k)
                                             : std::abs(clamp01(test) * 255.0 - k);
  }
  // The reference is clamped because the displayed range is [0, 1]: a reference value of 1.3
  // shows as white, and an output that shows white is right.
  const double r = clamp01(reference);
  if (encoding == TestEncoding::kUnorm8) {
    // O is the stored byte. to_unorm8 is how every 8-bit image is written (image.h), so an
    // in-memory render judged here gives the same figures as its PNG; on values read from an
    // 8-bit file (k/255) it gives back k exactly. Comparing k with 255 r keeps the 0.5 LSB
    // floor exact: no division by 255 on the 8-bit side.
    return std::abs(static_cast<double>(to_unorm8(test)) - r * 255.0);
  }
  // Float output, unquantised: clamped like the reference, for the same reason (a float image
  // is displayed through [0, 1] too), so overshoot beyond white or below black is not error.
  return std::abs(clamp01(test) - r) * 255.0;
}

double CoverageMismatch::percent() const {
  if (reference_covered == 0) return reference_only + test_only > 0 ? 100.0 : 0.0;
  return 100.0 * static_cast<double>(reference_only + test_only) /
         static_cast<double>(reference_covered);
}

Comparison compare_images(const Image& test, const Image& reference, TestEncoding encoding,
                          TestEncoding reference_encoding, Coverage coverage) {
  LT_CHECK(test.width == reference.width && test.height == reference.height,
           "test " + size_string(test) + " vs reference " + size_string(reference));
  LT_CHECK(test.rgba.size() == test.pixel_count() * 4 &&
               reference.rgba.size() == reference.pixel_count() * 4,
           "image storage does not match its size");
  Comparison out;
  out.width = test.width;
  out.height = test.height;
  out.encoding = encoding;
  out.coverage = coverage;
  out.pixel_error_lsb.assign(test.pixel_count(), 0.0);
  out.covered_mask.assign(test.pixel_count(), false);

  RegionAccumulator covered, image;
  for (int y = 0; y < test.height; ++y) {
    for (int x = 0; x < test.width; ++x) {
      const size_t i = static_cast<size_t>(y) * test.width + x;
      const float* o = test.at(x, y);
      const float* r = reference.at(x, y);
      LT_CHECK(pixel_is_finite(r),
               "non-finite reference value at " + std::to_string(x) + "," + std::to_string(y));
      const bool by_reference = is_covered(r[3]);
      out.covered_mask[i] = by_reference;
      if (coverage == Coverage::kBoth) {
        // A NaN alpha is no coverage; the pixel is counted non-finite below anyway.
        const bool by_test = is_covered(o[3]);
        out.mismatch.reference_covered += by_reference;
        out.mismatch.reference_only += by_reference && !by_test;
        out.mismatch.test_only += by_test && !by_reference;
        out.covered_mask[i] = by_reference && by_test;
      }
      if (!pixel_is_finite(o)) {
        for (int c = 0; c < 4; ++c) out.test_non_finite += std::isfinite(o[c]) ? 0 : 1;
        ++out.test_non_finite_pixels;
        out.pixel_error_lsb[i] = std::numeric_limits<double>::quiet_NaN();
        continue;
      }
      double e[3];
      for (int c = 0; c < 3; ++c)
        e[c] = channel_error_lsb(o[c], r[c], encoding, reference_encoding);
      out.pixel_error_lsb[i] = std::max({e[0], e[1], e[2]});
      image.add(x, y, e);
      if (out.covered_mask[i]) covered.add(x, y, e);
    }
  }
  out.covered = covered.finish();
  out.image = image.finish();
  fill_shift_errors(test, reference, encoding, reference_encoding, out);
  return out;
}

EdgeShiftSplit split_edge_shifts(const Comparison& comparison, double threshold_lsb,
                                 Region region) {
  EdgeShiftSplit split;
  for (size_t i = 0; i < comparison.pixel_error_lsb.size(); ++i) {
    if (region == Region::kCovered && !comparison.covered_mask[i]) continue;
    const double e = comparison.pixel_error_lsb[i];
    if (!std::isfinite(e)) continue;
    const bool over = e > threshold_lsb;
    const bool shifted = over && comparison.pixel_shift_error_lsb[i] <= threshold_lsb;
    split.edge_shift_pixels += shifted;
    split.shading_pixels += over && !shifted;
    if (!shifted) split.shading_max_lsb = std::max(split.shading_max_lsb, e);
  }
  return split;
}

Verdict apply_tolerance(const Comparison& comparison, const Tolerance& tolerance) {
  LT_CHECK(
      tolerance.fail_lsb >= 0.0 && tolerance.fail_percent >= 0.0 && tolerance.hard_fail_lsb >= 0.0,
      "tolerances must be >= 0 (the CLI rejects others as bad input)");
  Verdict v;
  const ErrorStats& stats = region_stats(comparison, tolerance.region);
  const std::string where = to_string(tolerance.region);
  const EdgeShiftSplit split = split_edge_shifts(comparison, tolerance.fail_lsb, tolerance.region);
  v.edge_shift_pixels = split.edge_shift_pixels;
  v.shading_pixels = split.shading_pixels;
  v.shading_max_lsb = split.shading_max_lsb;
  const double edge_shift_percent =
      stats.pixels > 0
          ? 100.0 * static_cast<double>(split.edge_shift_pixels) / static_cast<double>(stats.pixels)
          : 0.0;
  // Within its share, an edge shift is left out of every criterion below: the shading pixels
  // stay held to the LSB bounds.
  v.edge_shifts_excused =
      tolerance.edge_shift_percent > 0.0 && edge_shift_percent <= tolerance.edge_shift_percent;
  size_t judged_failing = 0, warning_pixels = 0, hard_warning_pixels = 0;
  double judged_max = 0.0;
  for (size_t i = 0; i < comparison.pixel_error_lsb.size(); ++i) {
    if (tolerance.region == Region::kCovered && !comparison.covered_mask[i]) continue;
    const double e = comparison.pixel_error_lsb[i];
    if (!std::isfinite(e)) continue;  // counted as non-finite below, not as error
    if (e > tolerance.fail_lsb) ++v.failing_pixels;
    if (v.edge_shifts_excused && e > tolerance.fail_lsb &&
        comparison.pixel_shift_error_lsb[i] <= tolerance.fail_lsb)
      continue;
    judged_max = std::max(judged_max, e);
    if (e > tolerance.fail_lsb) ++judged_failing;
    if (e > tolerance.hard_fail_lsb) ++v.hard_failing_pixels;
    if (e > tolerance.warn_lsb) ++warning_pixels;
    if (e > tolerance.hard_warn_lsb) ++hard_warning_pixels;
  }
  auto percent_of_region = [&](size_t n) {
    return stats.pixels > 0 ? 100.0 * static_cast<double>(n) / static_cast<double>(stats.pixels)
                            : 0.0;
  };
  // Percent of the region's finite pixels, the same denominator as the reported figures.
  v.failing_percent = percent_of_region(v.failing_pixels);
  const double judged_percent = percent_of_region(judged_failing);
  const std::string excused =
      v.edge_shifts_excused && split.edge_shift_pixels > 0
          ? " (besides " + std::to_string(split.edge_shift_pixels) + " edge shifts)"
          : "";
  // The max a reason names: the largest error the criteria judged.
  const std::string max_text =
      v.edge_shifts_excused
          ? "shading max " + lsb_string(judged_max) + " LSB"
          : "max " + lsb_string(stats.max_lsb) + " LSB at " + location_string(stats);

  if (comparison.test_non_finite > 0) {
    v.reasons.push_back(std::to_string(comparison.test_non_finite) +
                        " non-finite values (NaN/Inf) in the test image, in " +
                        std::to_string(comparison.test_non_finite_pixels) + " pixels");
  }
  if (tolerance.edge_shift_percent > 0.0 && !v.edge_shifts_excused) {
    v.reasons.push_back(format("%g", edge_shift_percent) + "% of " + where + " pixels (" +
                        std::to_string(split.edge_shift_pixels) + ") are edge shifts, allowed " +
                        format("%g", tolerance.edge_shift_percent) + "%");
  }
  v.over_fail_percent = judged_percent > tolerance.fail_percent;
  if (v.over_fail_percent) {
    v.reasons.push_back(format("%g", judged_percent) + "% of " + where + " pixels (" +
                        std::to_string(judged_failing) + " of " + std::to_string(stats.pixels) +
                        ") have error > " + format("%g", tolerance.fail_lsb) + " LSB" + excused +
                        ", allowed " + format("%g", tolerance.fail_percent) + "%");
  }
  if (v.hard_failing_pixels > 0) {
    v.reasons.push_back(std::to_string(v.hard_failing_pixels) + " " + where +
                        " pixels have error > " + format("%g", tolerance.hard_fail_lsb) + " LSB" +
                        excused + " (" + max_text + ")");
  }
  if (comparison.coverage == Coverage::kBoth &&
      comparison.mismatch.percent() > tolerance.max_mismatch_percent) {
    const CoverageMismatch& m = comparison.mismatch;
    v.reasons.push_back("coverage differs on " + format("%g", m.percent()) +
                        "% of the reference's covered pixels (" + std::to_string(m.reference_only) +
                        " covered only by the reference, " + std::to_string(m.test_only) +
                        " only by the test), allowed " +
                        format("%g", tolerance.max_mismatch_percent) + "%");
  }
  v.pass = v.reasons.empty();
  if (!v.pass) return v;
  // idiff's order: a failure is only a failure; the warn tier speaks for what passes.
  const double warning_percent = percent_of_region(warning_pixels);
  if (warning_percent > tolerance.warn_percent) {
    v.warnings.push_back(format("%g", warning_percent) + "% of " + where + " pixels (" +
                         std::to_string(warning_pixels) + " of " + std::to_string(stats.pixels) +
                         ") have error > " + format("%g", tolerance.warn_lsb) + " LSB" + excused +
                         ", warn over " + format("%g", tolerance.warn_percent) + "%");
  }
  if (hard_warning_pixels > 0) {
    v.warnings.push_back(std::to_string(hard_warning_pixels) + " " + where +
                         " pixels have error > " + format("%g", tolerance.hard_warn_lsb) + " LSB" +
                         excused + " (" + max_text + ")");
  }
  v.warn = !v.warnings.empty();
  return v;
}

TestEncoding encoding_of(const std::filesystem::path& path) {
  return image_file_is_8bit(path) ? TestEncoding::kUnorm8 : TestEncoding::kFloat;
}

Comparison compare_files(const std::filesystem::path& test,
                         const std::filesystem::path& reference) {
  const Image test_image = read_image(test);
  const Image reference_image = read_image(reference);
  const TestEncoding encoding = encoding_of(test);
  const TestEncoding reference_encoding = encoding_of(reference);
  // What makes a reference: the float image (the reference path's EXR, alpha = coverage) that an
  // 8-bit render is judged against. An 8-bit REF with a float TEST can only be the two swapped:
  // judged that way round the float image would be measured against a quantised copy of itself.
  if (encoding == TestEncoding::kFloat && reference_encoding == TestEncoding::kUnorm8) {
    throw InputError(reference.string(), "",
                     "REF is an 8-bit image and TEST " + test.string() +
                         " a float one: the float reference comes second (ltrender compare " +
                         reference.string() + " " + test.string() + ")");
  }
  if (test_image.width != reference_image.width || test_image.height != reference_image.height) {
    throw InputError(test.string(), "",
                     "size " + size_string(test_image) + " does not match the reference " +
                         reference.string() + " (" + size_string(reference_image) + ")");
  }
  // A reference is ours and finite by construction; a non-finite one is a broken file, not a
  // failed comparison.
  for (int y = 0; y < reference_image.height; ++y) {
    for (int x = 0; x < reference_image.width; ++x) {
      if (!pixel_is_finite(reference_image.at(x, y))) {
        throw InputError(reference.string(), "pixel " + std::to_string(x) + "," + std::to_string(y),
                         "non-finite value (NaN/Inf) in the reference");
      }
    }
  }
  const bool both = image_file_has_alpha(test) && image_file_has_alpha(reference);
  return compare_images(test_image, reference_image, encoding, reference_encoding,
                        both ? Coverage::kBoth : Coverage::kReference);
}

nlohmann::ordered_json to_json(const Comparison& comparison, const Tolerance& tolerance,
                               const Verdict& verdict) {
  return {
      {"encoding", to_string(comparison.encoding)},
      {"width", comparison.width},
      {"height", comparison.height},
      {"covered", stats_to_json(comparison.covered)},
      {"image", stats_to_json(comparison.image)},
      {"test_non_finite", comparison.test_non_finite},
      {"coverage_mismatch",
       comparison.coverage == Coverage::kBoth
           ? nlohmann::ordered_json{{"reference_only", comparison.mismatch.reference_only},
                                    {"test_only", comparison.mismatch.test_only},
                                    {"percent", comparison.mismatch.percent()}}
           : nlohmann::ordered_json()},
      {"thresholds",
       {
           {"fail_lsb", tolerance.fail_lsb},
           {"fail_percent", tolerance.fail_percent},
           {"hard_fail_lsb", number_or_null(tolerance.hard_fail_lsb)},
           {"region", to_string(tolerance.region)},
           {"max_mismatch_percent", tolerance.max_mismatch_percent},
           {"warn_lsb", number_or_null(tolerance.warn_lsb)},
           {"warn_percent", tolerance.warn_percent},
           {"hard_warn_lsb", number_or_null(tolerance.hard_warn_lsb)},
           {"edge_shift_percent", tolerance.edge_shift_percent},
       }},
      {"failing_pixels", verdict.failing_pixels},
      {"failing_percent", verdict.failing_percent},
      {"hard_failing_pixels", verdict.hard_failing_pixels},
      {"edge_shift_pixels", verdict.edge_shift_pixels},
      {"shading_pixels", verdict.shading_pixels},
      {"shading_max_lsb", verdict.shading_max_lsb},
      {"edge_shifts_excused", verdict.edge_shifts_excused},
      {"reasons", verdict.reasons},
      {"pass", verdict.pass},
      {"warn", verdict.warn},
      {"warnings", verdict.warnings},
  };
}

std::string to_table(const Comparison& comparison, const Tolerance& tolerance,
                     const Verdict& verdict) {
  const ErrorStats& c = comparison.covered;
  const ErrorStats& a = comparison.image;
  std::string out;
  auto row = [&out](const char* name, const std::string& covered, const std::string& image) {
    char buf[160];
    std::snprintf(buf, sizeof buf, "%-14s %14s %14s\n", name, covered.c_str(), image.c_str());
    out += buf;
  };
  out += std::to_string(comparison.width) + "x" + std::to_string(comparison.height) + ", test " +
         (comparison.encoding == TestEncoding::kUnorm8 ? "8-bit" : "float (unquantised)") +
         ", error in LSB of 8 bits\n";
  row("", comparison.coverage == Coverage::kBoth ? "both cover" : "covered", "image");
  row("pixels", std::to_string(c.pixels), std::to_string(a.pixels));
  row("max", lsb_string(c.max_lsb), lsb_string(a.max_lsb));
  row("  at x,y ch", location_string(c), location_string(a));
  row("mean", lsb_string(c.mean_lsb), lsb_string(a.mean_lsb));
  row("RMSE", lsb_string(c.rmse_lsb), lsb_string(a.rmse_lsb));
  row("PSNR dB", lsb_string(c.psnr_db), lsb_string(a.psnr_db));
  row("p99", lsb_string(c.p99_lsb), lsb_string(a.p99_lsb));
  row("% > 1 LSB", fixed(c.percent_over_1_lsb, 3), fixed(a.percent_over_1_lsb, 3));
  row("% > 4 LSB", fixed(c.percent_over_4_lsb, 3), fixed(a.percent_over_4_lsb, 3));
  out += "non-finite test values: " + std::to_string(comparison.test_non_finite) + "\n";
  if (comparison.coverage == Coverage::kBoth) {
    const CoverageMismatch& m = comparison.mismatch;
    out += "coverage: " + std::to_string(m.reference_only) + " pixels only the reference covers, " +
           std::to_string(m.test_only) + " only the test (" + fixed(m.percent(), 3) +
           "% of the reference's; allowed " + format("%g", tolerance.max_mismatch_percent) + "%)\n";
  }
  out += std::string("thresholds (") + to_string(tolerance.region) + " pixels): fail if > " +
         format("%g", tolerance.fail_percent) + "% have error > " +
         format("%g", tolerance.fail_lsb) + " LSB" +
         (std::isfinite(tolerance.hard_fail_lsb)
              ? ", or any has error > " + format("%g", tolerance.hard_fail_lsb) + " LSB"
              : std::string()) +
         "\n";
  out += "over fail_lsb: " + std::to_string(verdict.failing_pixels) + " pixels, " +
         std::to_string(verdict.edge_shift_pixels) + " edge shifts (each image holds the other's " +
         "value within one pixel) and " + std::to_string(verdict.shading_pixels) +
         " shading; shading max " + lsb_string(verdict.shading_max_lsb) + " LSB" +
         (tolerance.edge_shift_percent > 0.0
              ? ", edge shifts allowed on " + format("%g", tolerance.edge_shift_percent) + "%"
              : std::string()) +
         "\n";
  out += "result: " + std::string(!verdict.pass ? "FAIL" : verdict.warn ? "WARN" : "PASS") + "\n";
  for (const auto& reason : verdict.reasons) out += "  " + reason + "\n";
  for (const auto& warning : verdict.warnings) out += "  " + warning + "\n";
  return out;
}

const char* to_string(TestEncoding encoding) {
  return encoding == TestEncoding::kUnorm8 ? "unorm8" : "float";
}

const char* to_string(Region region) {
  return region == Region::kCovered ? "covered" : "image";
}

}  // namespace lt
