// The eight vertex formats (issue 46 step 8, gx variant :vat=N): the VAT of format N written to
// CP 0x70/0x80/0x90 + N reads back through the stream reader, which sizes a draw's vertices by
// the VAT its command's low three bits name (checked against the vertex loader's own size, a
// second implementation); a variant's frame names its format in every draw and decodes to the
// default frame's state; the pixels do not move; a program file declaring its storage in
// GX_VTXFMTn is read in the format that declares the position, and refused where a pass or two
// passes name two formats.
#include <gtest/gtest.h>

#include <algorithm>

#include "core/error.h"
#include "gx/fifo/cp_registers.h"
#include "gx/fifo/state_decoder.h"
#include "gx/fifo/stream_reader.h"
#include "gx/program/printer.h"
#include "gx/vertex_loader.h"
#include "load/load_scene.h"
#include "paths/gx/generator.h"
#include "paths/gx/gx_path.h"
#include "render/session.h"
#include "test_util.h"

namespace lt::gx {
namespace {

constexpr int kFormatWidth = 96, kFormatHeight = 72;

const Scene& format_scene() {
  static const Scene scene = load_scene(test::source_dir() / "scenes/baked_blob.json");
  return scene;
}

// A format unlike the default F32 one in every field the size depends on: s16/8 positions, an
// NBT of s8 normals (NBT3 when `index3`), RGB565 colour 0, RGBA4 colour 1, s16 ST in TEX0.
VertexAttributeFormat unusual_format(bool index3) {
  VertexAttributeFormat f;
  f.position = {3, ComponentType::S16, 8};
  f.normal = {ComponentType::S8, true, index3};
  f.color[0] = {false, ColorType::Rgb565};
  f.color[1] = {true, ColorType::Rgba4};
  f.texcoord[0] = {2, ComponentType::S16, 10};
  return f;
}

TEST(GxVertexFormats, TheVatOfEachFormatRoundTripsThroughTheStreamReader) {
  for (const AttributeInput input : {AttributeInput::Direct, AttributeInput::Index16}) {
    for (int n = 0; n < 8; ++n) {
      const std::string where =
          "format " + std::to_string(n) + " input " + std::to_string(static_cast<int>(input));
      const VertexAttributeFormat format = unusual_format(input != AttributeInput::Direct);
      VertexInputs inputs;
      inputs.position = inputs.normal = inputs.color[0] = inputs.color[1] = input;
      inputs.texcoord[0] = input;
      const size_t vertex_bytes = VertexLoader(inputs, format, where).vertex_size();
      fifo::CommandStream out;
      // Every other format left as the default F32 one: reading any VAT but n sizes the
      // vertices otherwise and the stream falls out of step.
      for (int other = 0; other < 8; ++other)
        if (other != n) fifo::write_vat(out, pack_vertex_format(VertexAttributeFormat{}), other);
      const std::array<u32, 2> vcd = pack_vertex_inputs(inputs);
      out.load_cp(fifo::cp::kVcdLow, vcd[0]);
      out.load_cp(fifo::cp::kVcdHigh, vcd[1]);
      fifo::write_vat(out, pack_vertex_format(format), n);
      out.begin(0, static_cast<u8>(n), 3);  // GX_QUADS, three vertices: the bytes are all read
      for (size_t b = 0; b < 3 * vertex_bytes; ++b) out.put_u8(0);
      out.load_bp(0x52, 0);  // after the draw: the reader must land on it
      fifo::RegisterFile regs;
      const fifo::StreamEvents ev = fifo::read_stream(out.bytes(), regs, where);
      ASSERT_EQ(ev.draws.size(), 1u) << where;
      EXPECT_EQ(ev.draws[0].vat, n) << where;
      EXPECT_EQ(ev.draws[0].vertex_size, vertex_bytes) << where;
      EXPECT_EQ(ev.copies.size(), 1u) << where;
      const auto i = static_cast<size_t>(n);
      EXPECT_EQ(unpack_vertex_format(regs.cp[0x70 + i], regs.cp[0x80 + i], regs.cp[0x90 + i]),
                format)
          << where;
    }
  }
  // The sizes the loader gives, by Dolphin's rule [DHW VertexLoader_Normal.cpp GetSize]: beside
  // an s16 position (6 bytes), an NBT of s8 sends 9 bytes directly, one GX_INDEX16 (2) indexed,
  // three (6) under NBT3.
  VertexInputs nbt;
  nbt.position = nbt.normal = AttributeInput::Direct;
  EXPECT_EQ(VertexLoader(nbt, unusual_format(false), "nbt").vertex_size(), 6u + 9u);
  nbt.normal = AttributeInput::Index16;
  EXPECT_EQ(VertexLoader(nbt, unusual_format(false), "nbt").vertex_size(), 6u + 2u);
  EXPECT_EQ(VertexLoader(nbt, unusual_format(true), "nbt3").vertex_size(), 6u + 6u);
}

// Each draw of the frame, as the stream reader walks it: the VAT it names, the bytes a vertex
// and what the descriptor and that VAT decode to.
struct FormatDraw {
  u8 vat;
  size_t vertex_size;
  VertexDescriptor vertex;
  TexCoordFormats texcoords;
};
std::vector<FormatDraw> frame_draws(const std::string& variant, const std::string& program = "") {
  const std::vector<u8> log = gx_path_info().fifo_log(
      format_scene(), variant, PathOptions{program, ""}, kFormatWidth, kFormatHeight);
  const fifo::FifoLog read = fifo::read_fifo_log(log, variant);
  std::vector<FormatDraw> out;
  fifo::RegisterFile regs;
  fifo::read_stream(read.frames.at(0).fifo, regs, variant,
                    [&](const fifo::RegisterFile& r, const fifo::StreamDraw& d) {
                      const GxState s = fifo::decode_pass(r, d.vat).state;
                      out.push_back({d.vat, d.vertex_size, s.vertex, s.texcoord_formats});
                    });
  return out;
}

TEST(GxVertexFormats, EveryDrawOfAVariantNamesItsFormatAndReadsWhatFormatZeroWould) {
  for (const std::string stored : {"", ":vtx=s16/8:nrm=s8:clr=rgb565:draw=indexed"}) {
    const std::vector<FormatDraw> zero = frame_draws("t=vertex" + stored);
    for (int n : {3, 7}) {
      const std::string variant = "t=vertex" + stored + ":vat=" + std::to_string(n);
      const std::vector<FormatDraw> draws = frame_draws(variant);
      ASSERT_EQ(draws.size(), zero.size()) << variant;
      ASSERT_FALSE(draws.empty());
      for (size_t k = 0; k < draws.size(); ++k) {
        EXPECT_EQ(draws[k].vat, n) << variant << " draw " << k;
        EXPECT_EQ(zero[k].vat, 0) << stored << " draw " << k;
        EXPECT_EQ(draws[k].vertex_size, zero[k].vertex_size) << variant << " draw " << k;
        EXPECT_EQ(draws[k].vertex, zero[k].vertex) << variant << " draw " << k;
        EXPECT_EQ(draws[k].texcoords, zero[k].texcoords) << variant << " draw " << k;
      }
    }
    // The emulator's frame does not move: the eight VATs differ only in their number.
    EXPECT_EQ(
        render_scene(format_scene(), "gx", "t=vertex" + stored + ":vat=7", kFormatWidth,
                     kFormatHeight)
            .rgba,
        render_scene(format_scene(), "gx", "t=vertex" + stored, kFormatWidth, kFormatHeight).rgba)
        << stored;
  }
  EXPECT_EQ(to_string(parse_gx_variant("t=vertex:vat=5")), "t=vertex:vat=5");
  EXPECT_EQ(to_string(parse_gx_variant("t=vertex:vat=0")), "t=vertex");
  for (const char* bad : {"t=vertex:vat=8", "t=vertex:vat=-1", "t=vertex:vat=x"})
    EXPECT_THROW(parse_gx_variant(bad), InputError) << bad;
}

const std::vector<std::pair<std::string, std::string>> kFormat3S16 = {
    {"GX_SetVtxAttrFmt(GX_VTXFMT0", "GX_SetVtxAttrFmt(GX_VTXFMT3"},
    {"GX_VA_POS, GX_POS_XYZ, GX_F32, 0", "GX_VA_POS, GX_POS_XYZ, GX_S16, 8"},
    {"GX_VA_NRM, GX_NRM_XYZ, GX_F32, 0", "GX_VA_NRM, GX_NRM_XYZ, GX_S8, 0"}};

std::string f32_program() {
  return print_program(generate_programs(format_scene(), parse_gx_variant("t=vertex")).file);
}

// A program that stores the mesh in GX_VTXFMT3 and declares GX_VTXFMT0 and 1 otherwise (as a
// game sets up several formats at start-up) draws GX_VTXFMT3's storage: its FIFO log is the
// variant's with :vat=3, and the generated program of that variant declares GX_VTXFMT3.
TEST(GxVertexFormats, AProgramIsReadInTheFormatThatDeclaresThePosition) {
  test::TempDir dir;
  auto edits = kFormat3S16;
  edits.push_back({"GX_ClearVtxDesc();",
                   "GX_ClearVtxDesc();\n  GX_SetVtxAttrFmt(GX_VTXFMT1, GX_VA_NRM, GX_NRM_XYZ, "
                   "GX_S16, 0);\n  GX_SetVtxAttrFmt(GX_VTXFMT0, GX_VA_CLR0, GX_CLR_RGB, "
                   "GX_RGBA4, 0);"});
  const fs::path file = dir / "format3.c";
  test::write_file(file, test::with_edits(f32_program(), edits));
  const PathInfo& gx = gx_path_info();
  const std::string variant = "t=vertex:vtx=s16/8:nrm=s8:vat=3";
  EXPECT_EQ(gx.fifo_log(format_scene(), "t=vertex", PathOptions{file.string(), ""}, kFormatWidth,
                        kFormatHeight),
            gx.fifo_log(format_scene(), variant, {}, kFormatWidth, kFormatHeight));
  const std::string generated =
      print_program(generate_programs(format_scene(), parse_gx_variant(variant)).file);
  EXPECT_EQ(generated, test::with_edits(f32_program(), kFormat3S16));
  EXPECT_EQ(generated.find("GX_VTXFMT0"), std::string::npos);
}

// Two formats for the scene's draws, or a :vat= axis against the file's: one line names it.
TEST(GxVertexFormats, TwoFormatsForTheDrawsAreRefusedNamingTheLine) {
  test::TempDir dir;
  const std::string f32 = f32_program();
  auto refused_at = [&](const std::string& text, const std::string& variant,
                        const std::string& file_named, int line, const std::string& message) {
    const fs::path file = dir / "two_formats.c";
    test::write_file(file, text);
    try {
      (void)scene_programs_for(format_scene(), parse_gx_variant(variant), file.string());
      ADD_FAILURE() << message << ": accepted";
    } catch (const InputError& e) {
      EXPECT_EQ(e.file(), file_named == "file" ? file.string() : file_named) << e.what();
      if (line > 0)
        EXPECT_EQ(e.where().substr(0, e.where().find(':')), std::to_string(line)) << e.what();
      EXPECT_NE(std::string(e.what()).find(message), std::string::npos) << e.what();
      EXPECT_EQ(test::count_lines(std::string(e.what()) + "\n"), 1);
    }
  };
  // One pass declares the position in GX_VTXFMT0, then again in GX_VTXFMT5.
  const std::string pos = "GX_SetVtxAttrFmt(GX_VTXFMT0, GX_VA_POS, GX_POS_XYZ, GX_F32, 0);";
  std::string twice = f32;
  twice.replace(twice.find(pos), pos.size(),
                pos + "\n  GX_SetVtxAttrFmt(GX_VTXFMT5, GX_VA_POS, GX_POS_XYZ, GX_S16, 8);");
  refused_at(twice, "t=vertex", "file", test::line_holding(twice, "GX_VTXFMT5"),
             "is declared in GX_VTXFMT0");
  // The second pass alone draws with GX_VTXFMT6.
  std::string second = f32;
  const size_t at = second.find(pos, second.find(pos) + 1);
  ASSERT_NE(at, std::string::npos) << "baked_blob has one pass";
  second.replace(at, pos.size(), "GX_SetVtxAttrFmt(GX_VTXFMT6, GX_VA_POS, GX_POS_XYZ, GX_F32, 0);");
  refused_at(second, "t=vertex", "file", test::line_holding(second, "GX_VTXFMT6"),
             "alike in every pass");
  // The file draws with GX_VTXFMT3, the axis says 5.
  refused_at(test::with_edits(f32, kFormat3S16), "t=vertex:vat=5", "--variant", 0,
             "draws with GX_VTXFMT3");
}

// NBT normals (issue 46 step 8, `:nrm=s8/nbt`, `/nbt3`): the storage key reads back; the frame
// is the plain normal's to the byte (the XF lights the NBT's first vector alone [DSW
// TransformUnit.cpp TransformNormal, LightColor reads normal[0]], and the normal's stored bytes
// are the same); each vertex grows by the binormal's and tangent's bytes directly, and by two
// indices under NBT3 indexed; a program declaring GX_VA_NBT is the variant.

TEST(GxVertexFormats, TheBinormalAndTangentAreAnOrthonormalFrameOfTheNormal) {
  for (const glm::vec3 n :
       {glm::vec3(0, 0, 1), glm::vec3(0, 0, -1), glm::vec3(1, 0, 0),
        glm::normalize(glm::vec3(1, -2, 0.5f)), glm::normalize(glm::vec3(-0.3f, 0.1f, -0.9f))}) {
    const auto [b, t] = normal_frame(n);
    EXPECT_NEAR(glm::dot(n, b), 0.0f, 1e-6f);
    EXPECT_NEAR(glm::dot(n, t), 0.0f, 1e-6f);
    EXPECT_NEAR(glm::dot(b, t), 0.0f, 1e-6f);
    EXPECT_NEAR(glm::length(b), 1.0f, 1e-6f);
    EXPECT_NEAR(glm::length(t), 1.0f, 1e-6f);
  }
  for (const char* key : {"s8/nbt", "s16/nbt3", "f32/nbt"}) {
    VertexStorage s;
    set_vertex_storage(s, "nrm", key, "test");
    EXPECT_EQ(vertex_storage_value(s, "nrm"), key);
    EXPECT_FALSE(s.is_default());
  }
  VertexStorage s;
  EXPECT_THROW(set_vertex_storage(s, "nrm", "u8/nbt", "test"), InputError);
  EXPECT_THROW(set_vertex_storage(s, "nrm", "s8/xyz", "test"), InputError);
}

TEST(GxVertexFormats, AnNbtDrawsThePlainNormalsFrameAndSendsItsVectors) {
  const std::string plain = "t=vertex:vtx=s16/8:nrm=s8";
  const std::vector<FormatDraw> normal = frame_draws(plain);
  const std::vector<FormatDraw> indexed = frame_draws(plain + ":draw=indexed");
  const Image image = render_scene(format_scene(), "gx", plain, kFormatWidth, kFormatHeight);
  // s8 vectors of three bytes: direct, the binormal and the tangent add six bytes a vertex;
  // indexed, NBT adds none (one index to a 9-byte element) and NBT3 two more indices of the
  // normal's index size (GX_INDEX8 or GX_INDEX16: 2 or 4 bytes).
  struct NbtCase {
    std::string variant;
    const std::vector<FormatDraw>* base;
    std::vector<size_t> more_bytes;  // any of these
    bool render;
  };
  for (const NbtCase& c :
       {NbtCase{plain + "/nbt", &normal, {6}, true}, NbtCase{plain + "/nbt3", &normal, {6}, false},
        NbtCase{plain + "/nbt:draw=indexed", &indexed, {0}, false},
        NbtCase{plain + "/nbt3:draw=indexed", &indexed, {2, 4}, true}}) {
    const std::vector<FormatDraw> draws = frame_draws(c.variant);
    ASSERT_EQ(draws.size(), c.base->size()) << c.variant;
    for (size_t k = 0; k < draws.size(); ++k) {
      const size_t grew = draws[k].vertex_size - (*c.base)[k].vertex_size;
      EXPECT_NE(std::find(c.more_bytes.begin(), c.more_bytes.end(), grew), c.more_bytes.end())
          << c.variant << " draw " << k << " grew by " << grew;
    }
    if (c.render)
      EXPECT_EQ(render_scene(format_scene(), "gx", c.variant, kFormatWidth, kFormatHeight).rgba,
                image.rgba)
          << c.variant;
  }
}

// A program declaring the normal as an NBT3, indexed, as libogc takes it (GX_VA_NBT in the
// descriptor and the format) writes the variant's FIFO log; the variant's generated program
// declares exactly that; GX_VA_NRM with GX_NRM_NBT (which libogc ignores) is refused.
TEST(GxVertexFormats, AProgramDeclaringGxVaNbtIsTheVariant) {
  test::TempDir dir;
  const std::string variant = "t=vertex:vtx=s16/8:nrm=s8/nbt3:draw=indexed";
  const std::string generated =
      print_program(generate_programs(format_scene(), parse_gx_variant(variant)).file);
  EXPECT_NE(generated.find("GX_SetVtxDesc(GX_VA_NBT, GX_INDEX"), std::string::npos);
  EXPECT_NE(generated.find("GX_VA_NBT, GX_NRM_NBT3, GX_S8, 0"), std::string::npos);
  const fs::path file = dir / "nbt3.c";
  test::write_file(file, generated);
  const PathInfo& gx = gx_path_info();
  EXPECT_EQ(gx.fifo_log(format_scene(), "t=vertex", PathOptions{file.string(), ""}, kFormatWidth,
                        kFormatHeight),
            gx.fifo_log(format_scene(), variant, {}, kFormatWidth, kFormatHeight));
  std::string wrong = f32_program();
  const std::string from = "GX_VA_NRM, GX_NRM_XYZ, GX_F32, 0";
  wrong.replace(wrong.find(from), from.size(), "GX_VA_NRM, GX_NRM_NBT, GX_S8, 0");
  test::write_file(file, wrong);
  try {
    (void)scene_programs_for(format_scene(), parse_gx_variant("t=vertex"), file.string());
    ADD_FAILURE() << "GX_VA_NRM with GX_NRM_NBT accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where().substr(0, e.where().find(':')),
              std::to_string(test::line_holding(wrong, "GX_NRM_NBT")));
    EXPECT_NE(std::string(e.what()).find("libogc ignores"), std::string::npos) << e.what();
  }
}

// GX_VA_CLR1 (issue 46 step 8): a program may send the scene's one vertex colour in GX_VA_CLR1,
// stored as GX_VA_CLR0 would be (the storage key's clr). Sent alone it feeds channel 0, as
// Dolphin's software renderer directs it [DSW SWVertexLoader.cpp ParseColorAttributes], so the
// program that sends CLR1 where the generated one sends CLR0 draws the generated frame (an
// expectation from the rule, not from the output); the two colours declared otherwise are
// refused at the second.

TEST(GxVertexFormats, AColourSentInClr1AloneDrawsTheClr0Frame) {
  test::TempDir dir;
  const fs::path file = dir / "clr1.c";
  const std::vector<std::pair<std::string, std::string>> to_clr1 = {
      {"GX_SetVtxDesc(GX_VA_CLR0", "GX_SetVtxDesc(GX_VA_CLR1"},
      {"GX_VA_CLR0, GX_CLR_RGBA, GX_RGBA8, 0", "GX_VA_CLR1, GX_CLR_RGB, GX_RGB565, 0"}};
  const std::string text = test::with_edits(f32_program(), to_clr1);
  ASSERT_EQ(text.find("GX_VA_CLR0"), std::string::npos);
  test::write_file(file, text);
  PathOptions options;
  options.program_file = file.string();
  const Image clr1 =
      render_scene(format_scene(), "gx", "t=vertex", kFormatWidth, kFormatHeight, options);
  const Image clr0 =
      render_scene(format_scene(), "gx", "t=vertex:clr=rgb565", kFormatWidth, kFormatHeight);
  EXPECT_EQ(clr1.rgba, clr0.rgba);
  EXPECT_NE(clr1.rgba,
            render_scene(format_scene(), "gx", "t=vertex", kFormatWidth, kFormatHeight).rgba)
      << "the RGB565 declaration changed nothing";
  // Its FIFO log sends CLR1 (VCD bits 15-16) and no CLR0 (13-14), two bytes of RGB565.
  const std::vector<FormatDraw> draws = frame_draws("t=vertex", file.string());
  const std::vector<FormatDraw> zero = frame_draws("t=vertex:clr=rgb565");
  ASSERT_EQ(draws.size(), zero.size());
  for (size_t k = 0; k < draws.size(); ++k) {
    EXPECT_TRUE(draws[k].vertex.has(kVaClr1) && !draws[k].vertex.has(kVaClr0)) << k;
    EXPECT_EQ(draws[k].vertex_size, zero[k].vertex_size) << k;
  }
  // CLR0 and CLR1 in two encodings: refused at the second.
  std::string both = f32_program();
  const std::string clr0_call =
      "GX_SetVtxAttrFmt(GX_VTXFMT0, GX_VA_CLR0, GX_CLR_RGBA, GX_RGBA8, 0);";
  both.replace(
      both.find(clr0_call), clr0_call.size(),
      clr0_call + "\n  GX_SetVtxAttrFmt(GX_VTXFMT0, GX_VA_CLR1, GX_CLR_RGBA, GX_RGBA4, 0);");
  test::write_file(file, both);
  try {
    (void)scene_programs_for(format_scene(), parse_gx_variant("t=vertex"), file.string());
    ADD_FAILURE() << "two colour encodings accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where().substr(0, e.where().find(':')),
              std::to_string(test::line_holding(both, "GX_RGBA4")));
    EXPECT_NE(std::string(e.what()).find("stored alike"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace lt::gx
