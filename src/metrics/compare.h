// Error of a rendered image against the double-precision reference (metrics.md), in LSB of an
// 8-bit channel (1 LSB = 1/255). One library for `ltrender compare`, `ltrender bench` and the
// golden-image tests: compute a Comparison once, then judge it against a Tolerance (Filament's
// imagediff: the tolerance is data and the verdict is a struct, never a bare bool). The heatmap
// of a Comparison is in metrics/heatmap.h.
//
// What the figures are over:
//  - "channel" figures (max, mean, RMSE, PSNR) use every R, G, B value of the region; alpha is
//    never compared as a colour: the reference's alpha is its coverage mask, and the test's
//    alpha is its coverage where both images carry one (Coverage::kBoth: a path's render, an
//    EXR). Then "covered" is where both cover, and the pixels only one covers are counted apart
//    (CoverageMismatch): a rasteriser that samples elsewhere in the pixel (the gx path's, as the
//    console's: 9/16 of a pixel, rasteriser.h) moves silhouette pixels, which is coverage, not
//    shading error.
//  - "pixel" figures (99th percentile, percent over 1 and 4 LSB, the threshold counts) use one
//    error per pixel, the max over its three channels: a pixel is as wrong as its worst channel,
//    and "percent of pixels" then reads the same as idiff's failing-pixel fraction.
//  - A pixel with any non-finite TEST value (NaN/Inf in any of R, G, B, A) is left out of every
//    figure, which would otherwise all become NaN, and is counted in `test_non_finite`; any
//    non-finite value fails the comparison whatever the tolerance.
#pragma once

#include <cstddef>
#include <filesystem>
#include <limits>
#include <nlohmann/json_fwd.hpp>
#include <string>
#include <vector>

#include "image/image.h"

namespace lt {

// How the TEST image stores its values, which decides how it is compared (metrics.md).
enum class TestEncoding {
  kUnorm8,  // 8-bit file: O is the stored byte; an in-memory image is quantised by to_unorm8
  kFloat,   // half/float/16-bit file: compared unquantised
};

// Per-channel error in LSB of one TEST value against one reference value (the formula of
// metrics.md; see compare.cpp for why each side is clamped). `reference_encoding` is how the
// reference stores its values, with the same two meanings: kUnorm8 for an 8-bit golden, whose
// values are k/255 exactly and are compared as the bytes k (see compare.cpp).
double channel_error_lsb(float test, float reference, TestEncoding encoding,
                         TestEncoding reference_encoding = TestEncoding::kFloat);

// A pixel is covered when the reference's alpha (coverage) is over one half.
inline bool is_covered(float reference_alpha) {
  return reference_alpha > 0.5f;
}

struct ErrorStats {
  size_t pixels = 0;  // finite pixels in the region (the channel figures use 3 * pixels values)
  double max_lsb = 0.0;
  // Where max_lsb is (the first such value in reading order); -1 when the region is empty or has
  // no error at all: a location of "the largest of zeros" would point at a pixel for nothing.
  int max_x = -1, max_y = -1, max_channel = -1;
  double mean_lsb = 0.0;
  double rmse_lsb = 0.0;
  double psnr_db = std::numeric_limits<double>::infinity();  // peak 1.0; inf when RMSE is 0
  double p99_lsb = 0.0;             // nearest-rank 99th percentile of per-pixel error
  double percent_over_1_lsb = 0.0;  // percent of pixels whose error is > 1 LSB
  double percent_over_4_lsb = 0.0;  // percent of pixels whose error is > 4 LSB
};

// Whose alpha is coverage.
enum class Coverage {
  kReference,  // the reference's only (an 8-bit golden, a PNG without alpha): covered is where
               // the reference covers
  kBoth,       // both: covered is where both cover, the rest counted in CoverageMismatch
};

// Pixels one image covers and the other does not (Coverage::kBoth).
struct CoverageMismatch {
  size_t reference_only = 0, test_only = 0;
  size_t reference_covered = 0;  // the denominator of percent()
  double percent() const;        // (reference_only + test_only) / reference_covered, in %
};

struct Comparison {
  int width = 0, height = 0;
  TestEncoding encoding = TestEncoding::kUnorm8;
  Coverage coverage = Coverage::kReference;
  CoverageMismatch mismatch;   // zero unless coverage is kBoth
  ErrorStats covered;          // pixels the reference covers (and the test, with kBoth)
  ErrorStats image;            // every pixel
  size_t test_non_finite = 0;  // non-finite values (not pixels) in TEST, all four channels
  size_t test_non_finite_pixels = 0;
  // Per pixel, top row first: max-channel error in LSB (NaN for a non-finite pixel), and the
  // reference's coverage. Kept so that a Tolerance can be judged and a heatmap drawn later;
  // double, like the figures, so a threshold set to a reported max judges that max consistently.
  std::vector<double> pixel_error_lsb;
  std::vector<bool> covered_mask;
  // Per pixel: the error left when each image may take its value from within one pixel (the
  // 3x3 neighbourhood, clipped at the image's border), both ways: the larger of "how far the
  // test's value here lies outside what the reference spans around the pixel" and "how far the
  // reference's lies outside what the test spans", each at its worst channel (compare.cpp says
  // why "spans"). Small where an edge moved, large where a shade changed (split_edge_shifts).
  // At most pixel_error_lsb; equal to it at or under half an LSB; NaN where it is NaN.
  std::vector<double> pixel_shift_error_lsb;
};

// Which pixels the thresholds judge.
enum class Region {
  kCovered,  // default: the background is not the technique under test, and the
             // reference's coverage is ground truth (silhouette pixels still count)
  kImage,    // every pixel, so geometry drawn where the reference has none also fails
};

// idiff-style thresholds: fail if more than `fail_percent` percent of the region's pixels have
// error > `fail_lsb`, or if any pixel of the region has error > `hard_fail_lsb`.
// With Coverage::kBoth, the coverage mismatch fails past `max_mismatch_percent` of the
// reference's covered pixels: a sample point a fraction of a pixel off moves a thin line of
// silhouette pixels (the gx path: at most 0.142% on the demo scenes, docs/testing.md);
// more than that is geometry missing or extra, which the covered region alone would not see.
//
// The warn tier between pass and fail is idiff's (-warn, -warnpercent, -hardwarn): a comparison
// within the fail bounds still warns when more than `warn_percent` percent of the region's pixels
// have error > `warn_lsb`, or any has error > `hard_warn_lsb`. Off unless set (infinite).
struct Tolerance {
  double fail_lsb = 1.0;
  double fail_percent = 0.0;
  double hard_fail_lsb = std::numeric_limits<double>::infinity();
  Region region = Region::kCovered;
  double max_mismatch_percent = 5.0;
  double warn_lsb = std::numeric_limits<double>::infinity();
  double warn_percent = 0.0;
  double hard_warn_lsb = std::numeric_limits<double>::infinity();
  // Percent of the region's pixels that may be edge shifts (split_edge_shifts at fail_lsb)
  // whatever their error: those pixels are then left out of the fail criteria above, which go on
  // holding the shading pixels. 0: an edge shift is judged like any error.
  double edge_shift_percent = 0.0;
};

struct Verdict {
  bool pass = true;
  size_t failing_pixels = 0;  // error > fail_lsb in the region
  double failing_percent = 0.0;
  bool over_fail_percent = false;    // failing_percent > fail_percent: one of the reasons
  size_t hard_failing_pixels = 0;    // error > hard_fail_lsb in the region
  std::vector<std::string> reasons;  // one line per failed criterion; empty when pass
  // The pixels over fail_lsb, classed (split_edge_shifts); their sum is failing_pixels.
  size_t edge_shift_pixels = 0, shading_pixels = 0;
  double shading_max_lsb = 0.0;  // the largest error of a pixel that is not an edge shift
  bool edge_shifts_excused = false;  // within edge_shift_percent: left out of the criteria
  // The warn tier, judged only when the comparison passes: one line per warn criterion met.
  bool warn = false;
  std::vector<std::string> warnings;
};

// Pure computation on in-memory images. Both must have the same size (LT_CHECK: callers that
// take images from the user go through compare_files, which reports a mismatch as an
// InputError) and the reference must be finite (LT_CHECK, likewise).
Comparison compare_images(const Image& test, const Image& reference, TestEncoding encoding,
                          TestEncoding reference_encoding = TestEncoding::kFloat,
                          Coverage coverage = Coverage::kReference);

Verdict apply_tolerance(const Comparison& comparison, const Tolerance& tolerance);

// The pixels of a region whose error is over `threshold_lsb`, classed: an edge shift where each
// image holds the other's value within one pixel, between its neighbours' values
// (pixel_shift_error_lsb <= threshold_lsb: an edge or a silhouette moved, as a rasteriser
// sampling elsewhere or a camera a pixel or part of one off moves it), shading otherwise (a value neither image has nearby: a changed shade, a line or a shape
// that appeared or vanished). Vulkan CTS's position-deviation compare and pixelmatch's
// anti-aliasing detection ask the same question.
struct EdgeShiftSplit {
  size_t edge_shift_pixels = 0, shading_pixels = 0;
  double shading_max_lsb = 0.0;  // the largest error over the region's pixels but edge shifts
};
EdgeShiftSplit split_edge_shifts(const Comparison& comparison, double threshold_lsb,
                                 Region region);

// The encoding of an image file, from OpenImageIO's spec: 8-bit formats are kUnorm8, anything
// wider is kFloat. Throws InputError naming the file if it cannot be opened.
TestEncoding encoding_of(const std::filesystem::path& path);

// Reads both files and compares them, with Coverage::kBoth when both files have an alpha channel
// (an EXR from `ltrender render` has coverage as alpha; a PNG has none). Throws InputError for a
// missing or unreadable file, a size mismatch (naming both sizes), a reference with non-finite
// values, or a float TEST against an 8-bit REF: the arguments swapped, since a reference is never
// coarser than what it judges (the message says which file comes first).
Comparison compare_files(const std::filesystem::path& test, const std::filesystem::path& reference);

// All figures as one JSON object, keys in this order: "encoding", "width", "height", "covered" and
// "image" (ErrorStats; "max_at" is null for a region that is empty or has no error),
// "test_non_finite", "thresholds", "failing_pixels", "failing_percent", "hard_failing_pixels",
// "reasons", "pass". Infinite values (the PSNR of a region without error, the default
// hard_fail_lsb) are written as null: JSON has no infinity, and null cannot be mistaken for a
// measured number (the text table prints "inf").
nlohmann::ordered_json to_json(const Comparison& comparison, const Tolerance& tolerance,
                               const Verdict& verdict);

// A small readable table of the figures and the verdict, for the terminal.
std::string to_table(const Comparison& comparison, const Tolerance& tolerance,
                     const Verdict& verdict);

const char* to_string(TestEncoding encoding);
const char* to_string(Region region);

}  // namespace lt
