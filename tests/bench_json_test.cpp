// report.json's rows read back as they were written (report/bench_json.h): `bench --jobs` builds
// its report from the rows its jobs wrote, so a field lost on the way would be a figure lost.
#include "report/bench_json.h"

#include <gtest/gtest.h>

#include <limits>

#include "core/error.h"

namespace lt {
namespace {

// A row with every field set, each to a value no other field has.
BenchRow full_row() {
  BenchRow r;
  r.scene = "blob";
  r.path = "gx";
  r.variant = "t=vertex:lut=16";
  r.at_scene_size = {12.5, 11.25};
  r.at_wide = {101.75, 99.5};
  r.ratio_to_flat = 31.125;
  r.ratio = {31.125, 30.0625, 32.5, 17};
  r.settling_frames = 23;
  r.rounds = 3;
  ErrorStats e;
  e.pixels = 4321;
  e.max_lsb = 7.36;
  e.max_x = 40;
  e.max_y = 21;
  e.max_channel = 2;
  e.mean_lsb = 0.318;
  e.rmse_lsb = 0.75;
  e.psnr_db = 51.2;
  e.p99_lsb = 3.5;
  e.percent_over_1_lsb = 1.25;
  e.percent_over_4_lsb = 0.0625;
  r.error = e;
  for (std::size_t k = 0; k < FrameStats::kFields.size(); ++k)
    r.stats.*(FrameStats::kFields[k].second) = 1000.0 + static_cast<double>(k);
  r.shading_mpixels_per_s = 8.5;
  r.cost = "4 TEV stages, 1 pass";
  r.work = FrameWork{1.5e6, 2.5e4, "TEV stage", "XF light"};
  r.image = "images/blob__gx_t_vertex_lut_16.png";
  r.heatmap = "images/blob__gx_t_vertex_lut_16__heatmap.png";
  r.width = 320;
  r.height = 240;
  return r;
}

void expect_same(const BenchRow& a, const BenchRow& b) {
  EXPECT_EQ(a.scene, b.scene);
  EXPECT_EQ(a.path, b.path);
  EXPECT_EQ(a.variant, b.variant);
  EXPECT_EQ(a.at_scene_size.median_ms, b.at_scene_size.median_ms);
  EXPECT_EQ(a.at_scene_size.min_ms, b.at_scene_size.min_ms);
  EXPECT_EQ(a.at_wide.median_ms, b.at_wide.median_ms);
  EXPECT_EQ(a.at_wide.min_ms, b.at_wide.min_ms);
  EXPECT_EQ(a.ratio_to_flat, b.ratio_to_flat);
  EXPECT_EQ(a.ratio.median, b.ratio.median);
  EXPECT_EQ(a.ratio.low, b.ratio.low);
  EXPECT_EQ(a.ratio.high, b.ratio.high);
  EXPECT_EQ(a.ratio.pairs, b.ratio.pairs);
  EXPECT_EQ(a.settling_frames, b.settling_frames);
  EXPECT_EQ(a.rounds, b.rounds);
  ASSERT_EQ(a.error.has_value(), b.error.has_value());
  if (a.error) {
    EXPECT_EQ(a.error->pixels, b.error->pixels);
    EXPECT_EQ(a.error->max_lsb, b.error->max_lsb);
    EXPECT_EQ(a.error->max_x, b.error->max_x);
    EXPECT_EQ(a.error->max_y, b.error->max_y);
    EXPECT_EQ(a.error->max_channel, b.error->max_channel);
    EXPECT_EQ(a.error->mean_lsb, b.error->mean_lsb);
    EXPECT_EQ(a.error->rmse_lsb, b.error->rmse_lsb);
    EXPECT_EQ(a.error->psnr_db, b.error->psnr_db);
    EXPECT_EQ(a.error->p99_lsb, b.error->p99_lsb);
    EXPECT_EQ(a.error->percent_over_1_lsb, b.error->percent_over_1_lsb);
    EXPECT_EQ(a.error->percent_over_4_lsb, b.error->percent_over_4_lsb);
  }
  for (const auto& [name, field] : FrameStats::kFields)
    EXPECT_EQ(a.stats.*field, b.stats.*field) << name;
  EXPECT_EQ(a.shading_mpixels_per_s, b.shading_mpixels_per_s);
  EXPECT_EQ(a.cost, b.cost);
  ASSERT_EQ(a.work.has_value(), b.work.has_value());
  if (a.work) {
    EXPECT_EQ(a.work->pixel_ops, b.work->pixel_ops);
    EXPECT_EQ(a.work->vertex_ops, b.work->vertex_ops);
    EXPECT_EQ(a.work->pixel_operation, b.work->pixel_operation);
    EXPECT_EQ(a.work->vertex_operation, b.work->vertex_operation);
  }
  EXPECT_EQ(a.work_not_counted, b.work_not_counted);
  EXPECT_EQ(a.image, b.image);
  EXPECT_EQ(a.heatmap, b.heatmap);
  EXPECT_EQ(a.width, b.width);
  EXPECT_EQ(a.height, b.height);
}

// Through text, as the jobs' files are: every double comes back to the bit.
BenchRow through_text(const BenchRow& row) {
  const std::string text = bench_row_to_json(row).dump(2);
  return bench_row_from_json(nlohmann::json::parse(text), "jobs/0.json", "/rows/0");
}

TEST(BenchJson, EveryFieldOfARowReadsBackAsWritten) {
  const BenchRow row = full_row();
  expect_same(row, through_text(row));
}

// flat's row (no error, no figures) and a perfect match (PSNR inf, which JSON writes as null),
// and a path that counts no work (its reason kept).
TEST(BenchJson, EmptyFieldsAndAnInfinitePsnrReadBack) {
  BenchRow row = full_row();
  row.error->psnr_db = std::numeric_limits<double>::infinity();
  row.error->max_x = row.error->max_y = row.error->max_channel = -1;
  row.work.reset();
  row.work_not_counted = "GLSL has no count";
  row.stats = {};
  row.shading_mpixels_per_s.reset();
  expect_same(row, through_text(row));
  BenchRow flat = full_row();
  flat.error.reset();
  flat.heatmap.clear();
  expect_same(flat, through_text(flat));
}

TEST(BenchJson, AMissingOrMistypedKeyNamesTheFileAndItsPointer) {
  nlohmann::json j = bench_row_to_json(full_row());
  j.erase("size");
  try {
    bench_row_from_json(j, "jobs/0.json", "/rows/4");
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), "jobs/0.json");
    EXPECT_EQ(e.where(), "/rows/4/size");
  }
  j = bench_row_to_json(full_row());
  j["error"]["p99_lsb"] = "three";
  try {
    bench_row_from_json(j, "jobs/0.json", "/rows/4");
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where(), "/rows/4/error/p99_lsb");
  }
}

}  // namespace
}  // namespace lt
