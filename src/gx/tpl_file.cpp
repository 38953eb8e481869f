// libogc TPL files, written and read (tpl_file.h).
#include "gx/tpl_file.h"

#include <bit>
#include <cstdint>

#include "core/error.h"

namespace lt::gx {

namespace {

constexpr size_t kHeaderBytes = 12, kImageHeaderBytes = 36, kPaletteHeaderBytes = 12;

size_t align32(size_t n) {
  return (n + 31) & ~size_t{31};
}

void put_u16(std::vector<u8>& out, size_t at, u32 v) {
  out[at] = static_cast<u8>(v >> 8);
  out[at + 1] = static_cast<u8>(v);
}
void put_u32(std::vector<u8>& out, size_t at, u32 v) {
  for (int k = 0; k < 4; ++k) out[at + static_cast<size_t>(k)] = static_cast<u8>(v >> (24 - 8 * k));
}

}  // namespace

std::vector<u8> write_tpl(const std::vector<TplTexture>& textures) {
  // Layout: header, descriptor table, image headers, palette headers, then (32-byte aligned)
  // each texture's texels and palette.
  const size_t n = textures.size();
  size_t image_headers = kHeaderBytes + 8 * n;
  size_t palette_headers = image_headers + kImageHeaderBytes * n;
  size_t end = palette_headers;
  for (const TplTexture& t : textures)
    if (is_indexed(t.format)) end += kPaletteHeaderBytes;
  std::vector<size_t> data_at(n), tlut_at(n);
  for (size_t k = 0; k < n; ++k) {
    const TplTexture& t = textures[k];
    LT_CHECK(t.data.size() == mip_chain_bytes(t.format, t.width, t.height, t.levels),
             "TPL texture data must hold its whole mip chain");
    data_at[k] = align32(end);
    end = data_at[k] + t.data.size();
    if (is_indexed(t.format)) {
      LT_CHECK(!t.tlut.empty() && t.tlut.size() % 2 == 0, "a colour-indexed texture has a TLUT");
      tlut_at[k] = align32(end);
      end = tlut_at[k] + t.tlut.size();
    }
  }
  std::vector<u8> out(align32(end), 0);
  put_u32(out, 0, kTplVersion);
  put_u32(out, 4, static_cast<u32>(n));
  put_u32(out, 8, static_cast<u32>(kHeaderBytes));
  size_t palette_header = palette_headers;
  for (size_t k = 0; k < n; ++k) {
    const TplTexture& t = textures[k];
    const size_t ih = image_headers + kImageHeaderBytes * k;
    put_u32(out, kHeaderBytes + 8 * k, static_cast<u32>(ih));
    put_u16(out, ih, static_cast<u32>(t.height));
    put_u16(out, ih + 2, static_cast<u32>(t.width));
    put_u32(out, ih + 4, static_cast<u32>(t.format));
    put_u32(out, ih + 8, static_cast<u32>(data_at[k]));
    put_u32(out, ih + 12, t.wrap_s);
    put_u32(out, ih + 16, t.wrap_t);
    put_u32(out, ih + 20, t.min_filter);
    put_u32(out, ih + 24, t.mag_filter);
    put_u32(out, ih + 28, std::bit_cast<u32>(t.lod_bias));
    out[ih + 32] = t.edge_lod;
    out[ih + 33] = t.min_lod;
    out[ih + 34] = static_cast<u8>(t.levels - 1);
    std::copy(t.data.begin(), t.data.end(), out.begin() + static_cast<std::ptrdiff_t>(data_at[k]));
    if (is_indexed(t.format)) {
      put_u32(out, kHeaderBytes + 8 * k + 4, static_cast<u32>(palette_header));
      put_u16(out, palette_header, static_cast<u32>(t.tlut.size() / 2));
      put_u32(out, palette_header + 4, static_cast<u32>(t.tlut_format));
      put_u32(out, palette_header + 8, static_cast<u32>(tlut_at[k]));
      std::copy(t.tlut.begin(), t.tlut.end(),
                out.begin() + static_cast<std::ptrdiff_t>(tlut_at[k]));
      palette_header += kPaletteHeaderBytes;
    }
  }
  return out;
}

namespace {

// Big-endian reads that refuse to go past the end, naming the offset.
struct Reader {
  std::span<const u8> bytes;
  const std::string& file;

  [[noreturn]] void fail(size_t offset, const std::string& what) const {
    throw InputError(file, "offset " + std::to_string(offset), what);
  }
  void need(size_t offset, size_t count, const char* what) const {
    if (offset > bytes.size() || count > bytes.size() - offset)
      fail(offset, std::string(what) + " (" + std::to_string(count) +
                       " bytes) runs past the end of the file (" + std::to_string(bytes.size()) +
                       " bytes): truncated TPL");
  }
  u32 u16_at(size_t offset) const { return u32{bytes[offset]} << 8 | bytes[offset + 1]; }
  u32 u32_at(size_t offset) const { return u16_at(offset) << 16 | u16_at(offset + 2); }
};

TplTexture read_texture(const Reader& r, size_t descriptor) {
  r.need(descriptor, 8, "the texture descriptor");
  const size_t ih = r.u32_at(descriptor), ph = r.u32_at(descriptor + 4);
  r.need(ih, kImageHeaderBytes, "the image header");
  TplTexture t;
  t.height = static_cast<int>(r.u16_at(ih));
  t.width = static_cast<int>(r.u16_at(ih + 2));
  const std::optional<TexFormat> format =
      tex_format_from_number(static_cast<int>(r.u32_at(ih + 4)));
  if (!format) r.fail(ih + 4, "unknown texture format " + std::to_string(r.u32_at(ih + 4)));
  t.format = *format;
  if (t.width < 1 || t.width > kMaxTextureSize || t.height < 1 || t.height > kMaxTextureSize)
    r.fail(ih, "texture size " + std::to_string(t.width) + "x" + std::to_string(t.height) +
                   " is outside 1..1024 per side");
  t.wrap_s = r.u32_at(ih + 12);
  t.wrap_t = r.u32_at(ih + 16);
  for (size_t at : {ih + 12, ih + 16})
    if (r.u32_at(at) > 2)
      r.fail(at, "wrap mode " + std::to_string(r.u32_at(at)) +
                     " is not GX_CLAMP, GX_REPEAT or GX_MIRROR");
  t.min_filter = r.u32_at(ih + 20);
  t.mag_filter = r.u32_at(ih + 24);
  if (t.min_filter > 5)
    r.fail(ih + 20,
           "min filter " + std::to_string(t.min_filter) + " is not GX_NEAR .. GX_LIN_MIP_LIN");
  if (t.mag_filter > 1)
    r.fail(ih + 24, "mag filter " + std::to_string(t.mag_filter) + " is not GX_NEAR or GX_LINEAR");
  t.lod_bias = std::bit_cast<float>(r.u32_at(ih + 28));
  t.edge_lod = r.bytes[ih + 32];
  t.min_lod = r.bytes[ih + 33];
  t.levels = r.bytes[ih + 34] + 1;
  if (t.levels > full_mip_levels(t.width, t.height))
    r.fail(ih + 34, "max LOD " + std::to_string(t.levels - 1) + " is past the " +
                        std::to_string(full_mip_levels(t.width, t.height)) + " levels of a " +
                        std::to_string(t.width) + "x" + std::to_string(t.height) + " texture");
  const size_t data = r.u32_at(ih + 8);
  const size_t size = mip_chain_bytes(t.format, t.width, t.height, t.levels);
  r.need(data, size, "the texel data");
  t.data.assign(r.bytes.begin() + static_cast<std::ptrdiff_t>(data),
                r.bytes.begin() + static_cast<std::ptrdiff_t>(data + size));
  if (is_indexed(t.format)) {
    if (ph == 0)
      r.fail(descriptor + 4,
             std::string("a ") + format_info(t.format).name + " texture without a palette");
    r.need(ph, kPaletteHeaderBytes, "the palette header");
    const size_t entries = r.u16_at(ph);
    if (entries == 0 || entries > static_cast<size_t>(format_info(t.format).tlut_entries))
      r.fail(ph, std::to_string(entries) + " palette entries for a " + format_info(t.format).name +
                     " texture (1.." + std::to_string(format_info(t.format).tlut_entries) + ")");
    const u32 tlut_format = r.u32_at(ph + 4);
    if (tlut_format > 2) r.fail(ph + 4, "unknown TLUT format " + std::to_string(tlut_format));
    t.tlut_format = static_cast<TlutFormat>(tlut_format);
    const size_t at = r.u32_at(ph + 8);
    r.need(at, entries * 2, "the palette");
    t.tlut.assign(r.bytes.begin() + static_cast<std::ptrdiff_t>(at),
                  r.bytes.begin() + static_cast<std::ptrdiff_t>(at + entries * 2));
  }
  return t;
}

}  // namespace

std::vector<TplTexture> read_tpl(std::span<const u8> bytes, const std::string& file) {
  const Reader r{bytes, file};
  r.need(0, kHeaderBytes, "the TPL header");
  if (r.u32_at(0) != kTplVersion)
    r.fail(0, "not a TPL file (version " + std::to_string(r.u32_at(0)) + ", expected 0x0020AF30)");
  const size_t n = r.u32_at(4);
  if (n == 0) r.fail(4, "a TPL file of no textures");
  r.need(kHeaderBytes, 8 * n, "the texture descriptors");
  std::vector<TplTexture> textures;
  // The descriptors start at byte 12 whatever the header-size field says, as libogc reads them
  // [OGC tpl.c L16 TPL_HDR_DESCR_FIELD].
  for (size_t k = 0; k < n; ++k) textures.push_back(read_texture(r, kHeaderBytes + 8 * k));
  return textures;
}

}  // namespace lt::gx
