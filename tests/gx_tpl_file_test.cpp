// libogc TPL files (src/gx/tpl_file.h): the layout libogc's reader expects, worked out by hand
// for one texture, a write-read round trip of several textures (mip chain, palette), and corrupt
// or truncated files refused with the file and the offset named.
#include <gtest/gtest.h>

#include <cstring>

#include "core/error.h"
#include "gx/tpl_file.h"

namespace lt::gx {
namespace {

u32 be32(const std::vector<u8>& d, size_t at) {
  return u32{d[at]} << 24 | u32{d[at + 1]} << 16 | u32{d[at + 2]} << 8 | d[at + 3];
}

TplTexture sample_i8() {
  TplTexture t;
  t.format = TexFormat::I8;
  t.width = 8;
  t.height = 4;
  t.data.assign(32, 0);
  for (size_t k = 0; k < 32; ++k) t.data[k] = static_cast<u8>(k * 7);
  t.wrap_s = 1;
  t.mag_filter = 0;
  return t;
}

TEST(GxTplFile, OneTextureIsLaidOutAsLibogcReadsIt) {
  const std::vector<u8> d = write_tpl({sample_i8()});
  EXPECT_EQ(be32(d, 0), 0x0020AF30u);  // version
  EXPECT_EQ(be32(d, 4), 1u);           // textures
  EXPECT_EQ(be32(d, 8), 12u);          // header size
  EXPECT_EQ(be32(d, 12), 20u);         // image header right after the descriptor table
  EXPECT_EQ(be32(d, 16), 0u);          // no palette
  EXPECT_EQ(d[20] << 8 | d[21], 4);    // height first
  EXPECT_EQ(d[22] << 8 | d[23], 8);    // then width
  EXPECT_EQ(be32(d, 24), 1u);          // GX_TF_I8
  EXPECT_EQ(be32(d, 28), 64u);         // texels at the first 32-byte boundary after 56 bytes
  EXPECT_EQ(be32(d, 32), 1u);          // wrap s GX_REPEAT
  EXPECT_EQ(be32(d, 36), 0u);          // wrap t GX_CLAMP
  EXPECT_EQ(be32(d, 40), 1u);          // min filter GX_LINEAR
  EXPECT_EQ(be32(d, 44), 0u);          // mag filter GX_NEAR
  EXPECT_EQ(d[54], 0);                 // max LOD 0: no mipmaps
  ASSERT_EQ(d.size(), 96u);
  EXPECT_EQ(d[64 + 5], 35);
}

TEST(GxTplFile, TexturesRoundTrip) {
  TplTexture mip;
  mip.format = TexFormat::RGB565;
  mip.width = 16;
  mip.height = 8;
  mip.levels = 5;  // 16x8, 8x4, 4x2, 2x1, 1x1
  mip.data.assign(mip_chain_bytes(TexFormat::RGB565, 16, 8, 5), 0);
  for (size_t k = 0; k < mip.data.size(); ++k) mip.data[k] = static_cast<u8>(k * 13 + 1);
  mip.min_filter = 5;
  mip.lod_bias = -0.5f;
  mip.edge_lod = 1;
  TplTexture ci;
  ci.format = TexFormat::CI4;
  ci.width = 8;
  ci.height = 8;
  ci.data.assign(32, 0x12);
  ci.tlut_format = TlutFormat::RGB5A3;
  ci.tlut = {0x80, 0x00, 0xFF, 0xFF, 0x12, 0x34};
  const std::vector<TplTexture> textures{sample_i8(), mip, ci};
  const std::vector<u8> bytes = write_tpl(textures);
  EXPECT_EQ(read_tpl(bytes, "t.tpl"), textures);
  // Every block starts on a 32-byte boundary (GX's texture address alignment).
  for (size_t k = 0; k < 3; ++k) EXPECT_EQ(be32(bytes, be32(bytes, 12 + 8 * k) + 8) % 32, 0u);
}

// The InputError read_tpl throws for `bytes`, or none.
std::string tpl_refusal(const std::vector<u8>& bytes) {
  try {
    read_tpl(bytes, "bad.tpl");
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), "bad.tpl");
    EXPECT_EQ(e.where().rfind("offset ", 0), 0u) << e.where();
    return e.where() + ": " + e.what_only();
  }
  return "";
}

TEST(GxTplFile, TruncatedFilesAreRefusedAtEveryLength) {
  TplTexture ci;
  ci.format = TexFormat::CI8;
  ci.width = 8;
  ci.height = 4;
  ci.data.assign(32, 3);
  ci.tlut.assign(8, 0x11);
  const std::vector<u8> whole = write_tpl({ci});
  // The palette ends the file's meaningful bytes; the zero padding after it may go.
  const size_t needed = be32(whole, be32(whole, 16) + 8) + ci.tlut.size();
  for (size_t n = 0; n < needed; ++n) {
    const std::string why = tpl_refusal(std::vector<u8>(whole.begin(), whole.begin() + static_cast<std::ptrdiff_t>(n)));
    EXPECT_NE(why.find("truncated TPL"), std::string::npos) << n << ": " << why;
  }
  EXPECT_EQ(tpl_refusal(std::vector<u8>(whole.begin(), whole.begin() + static_cast<std::ptrdiff_t>(needed))), "");
}

TEST(GxTplFile, CorruptFieldsAreRefusedNamingTheirOffset) {
  const std::vector<u8> good = write_tpl({sample_i8()});
  auto with = [&](size_t at, u32 v) {
    std::vector<u8> d = good;
    for (int k = 0; k < 4; ++k) d[at + static_cast<size_t>(k)] = static_cast<u8>(v >> (24 - 8 * k));
    return tpl_refusal(d);
  };
  EXPECT_EQ(with(0, 0x12345678), "offset 0: not a TPL file (version 305419896, expected 0x0020AF30)");
  EXPECT_EQ(with(24, 7), "offset 24: unknown texture format 7");
  EXPECT_EQ(with(20, 0x00000008), "offset 20: texture size 8x0 is outside 1..1024 per side");
  EXPECT_EQ(with(32, 3), "offset 32: wrap mode 3 is not GX_CLAMP, GX_REPEAT or GX_MIRROR");
  EXPECT_EQ(with(52, 0x00000400),
            "offset 54: max LOD 4 is past the 4 levels of a 8x4 texture");
  EXPECT_NE(with(28, 0xFFFFFFF0).find("offset 4294967280: the texel data"), std::string::npos);
  // A CI4 texture whose descriptor names no palette.
  std::vector<u8> ci = good;
  ci[27] = 8;  // GX_TF_CI4 (8x8 tiles: 32 bytes for 8x4 too)
  EXPECT_EQ(tpl_refusal(ci), "offset 16: a CI4 texture without a palette");
}

}  // namespace
}  // namespace lt::gx
