// The interpreter's machinery, shared by its call tables (one file per hardware unit:
// calls_xf.cpp, calls_tev.cpp, calls_pixel.cpp): the prototype of a libogc call, and the machine
// that checks a call against it and holds the program's variables. Internal to program/.
#pragma once

#include <cmath>
#include <functional>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "core/error.h"
#include "gx/gx_state.h"
#include "gx/program/gx_names.h"
#include "gx/program/program_file.h"
#include "gx/tpl_file.h"

namespace lt::gx::interp {

// What a parameter of a libogc prototype takes.
// MeshArray: any name (GX_SetArray's array is the scene's mesh as stored: the program names it,
// ltrender holds its bytes).
enum class ParamKind {
  Int,
  F32,
  Color,
  ColorS10,
  LightRef,
  TexRef,
  TlutRef,
  TplRef,  // &name of a declared TPLFile
  String,  // a "file name"
  MtxName,
  ArrayName,
  MeshArray
};

struct Param {
  ParamKind kind;
  NameGroup group = NameGroup::Bool;  // Int: the GX_* names it accepts
  long long min = 0, max = 0;         // Int: the valid values
};

inline Param integer(NameGroup g, long long lo, long long hi) {
  return {ParamKind::Int, g, lo, hi};
}
inline Param f32() {
  return {ParamKind::F32};
}
inline Param of(ParamKind k) {
  return {k};
}

// libogc's software light object [OGC gx.c struct __gx_litobj]: what the GX_InitLight* helpers
// write, copied into XF by GX_LoadLightObj.
using LightObject = XfLight;

// libogc's texture object: GX_InitTexObj's arguments; the image is the named u8 array.
struct TexObject {
  TextureObject texture;
  std::string array;
  bool initialised = false;
  int tlut_name = -1;  // GX_InitTexObjCI's TLUT (GX_TLUT0..GX_BIGTLUT3); -1: a direct format
};

// libogc's TLUT object [OGC gx.c GX_InitTlutObj]: the palette array, its format and entries.
struct TlutObject {
  std::string array;
  u8 format = 0;
  int entries = 0;
  bool initialised = false;
};

// A palette GX_LoadTlut left in TMEM (gx/tmem.h tlut_region): its bytes and format.
struct LoadedTlut {
  std::vector<u8> bytes;
  u8 format = 0;
};

// libogc's TPLFile once TPL_OpenTPLFromFile / TPL_OpenTPLFromMemory opened it (calls_tpl.cpp):
// the textures it holds and the name errors give it.
struct TplObject {
  std::string source;  // the file as resolved, or `program.c:array`
  std::vector<TplTexture> textures;
  bool open = false;
};

// One run: the state, the program's variables, and the call being executed (for messages).

class Machine {
 public:
  explicit Machine(const std::string& file) : file_(file) {}

  void run(const std::vector<Statement>& block) {
    for (const Statement& s : block) {
      if (s.kind == Statement::Kind::Declaration) {
        declare(s.declaration);
      } else {
        execute(s.call);
      }
    }
  }

  GxState state;

  // Accessors for handlers: argument k of the current call, already checked against its kind.
  long long i(size_t k) const { return call_->args[k].value; }
  u8 u(size_t k) const { return static_cast<u8>(call_->args[k].value); }
  bool b(size_t k) const { return call_->args[k].value != 0; }
  float f(size_t k) const { return static_cast<float>(call_->args[k].number); }
  Color8 color(size_t k) const {
    const auto& c = call_->args[k].color;
    return {static_cast<u8>(c[0]), static_cast<u8>(c[1]), static_cast<u8>(c[2]),
            static_cast<u8>(c[3])};
  }
  ColorS10 color_s10(size_t k) const {
    const auto& c = call_->args[k].color;
    return {static_cast<s16>(c[0]), static_cast<s16>(c[1]), static_cast<s16>(c[2]),
            static_cast<s16>(c[3])};
  }
  LightObject& light(size_t k) { return lights_.at(call_->args[k].name); }
  TexObject& tex(size_t k) { return textures_.at(call_->args[k].name); }
  TlutObject& tlut(size_t k) { return tluts_.at(call_->args[k].name); }
  TplObject& tpl(size_t k) { return tpls_.at(call_->args[k].name); }
  // Bytes the program did not declare (a TPL's texels and palettes), held under `name` for the
  // texture and TLUT objects that point at them, as a declared array would be.
  void hold_bytes(const std::string& name, std::vector<u8> bytes) {
    arrays_[name] = std::move(bytes);
  }
  const std::string& program_file() const { return file_; }
  // The palettes loaded so far, by TLUT name (GX_LoadTlut).
  std::map<int, LoadedTlut> loaded_tluts;
  const TexMatrix& mtx(size_t k) const { return matrices_.at(call_->args[k].name); }
  const std::vector<u8>& bytes(size_t k) const { return arrays_.at(call_->args[k].name); }
  const std::string& name(size_t k) const { return call_->args[k].name; }
  const std::string& text(size_t k) const { return call_->args[k].text; }
  const std::vector<u8>& bytes_of(const std::string& array) const { return arrays_.at(array); }
  int line() const { return call_->pos.line; }  // of the current call
  int column() const { return call_->pos.column; }

  [[noreturn]] void fail_arg(size_t k, const std::string& what) const {
    fail(call_->args[k].pos, call_->function + " argument " + std::to_string(k + 1) + ": " + what);
  }
  [[noreturn]] void fail_call(const std::string& what) const {
    fail(call_->pos, call_->function + ": " + what);
  }

 private:
  [[noreturn]] void fail(const SourcePos& p, const std::string& what) const {
    throw InputError(file_, std::to_string(p.line) + ":" + std::to_string(p.column), what);
  }

  void declare(const Declaration& d) {
    if (lights_.count(d.name) || textures_.count(d.name) || tluts_.count(d.name) ||
        tpls_.count(d.name) || matrices_.count(d.name) || arrays_.count(d.name))
      fail(d.pos, "redefinition of " + d.name);
    switch (d.type) {
      case Declaration::Type::LightObj:
        lights_[d.name] = LightObject{};
        break;
      case Declaration::Type::TexObj:
        textures_[d.name] = TexObject{};
        break;
      case Declaration::Type::TlutObj:
        tluts_[d.name] = TlutObject{};
        break;
      case Declaration::Type::TplFile:
        tpls_[d.name] = TplObject{};
        break;
      case Declaration::Type::Mtx: {
        TexMatrix m{};
        for (size_t r = 0; r < 3; ++r)
          for (size_t c = 0; c < 4; ++c) m[r][c] = static_cast<float>(d.values[r * 4 + c]);
        matrices_[d.name] = m;
        break;
      }
      case Declaration::Type::ByteArray: {
        std::vector<u8> v;
        for (double x : d.values) v.push_back(static_cast<u8>(x));
        arrays_[d.name] = std::move(v);
        break;
      }
    }
  }

  void execute(const Call& c);

  void check_arg(size_t k, const Param& p) const {
    const Arg& a = call_->args[k];
    auto wrong = [&](const std::string& expected) {
      fail_arg(k, "expected " + expected + ", found '" + a.text + "'");
    };
    switch (p.kind) {
      case ParamKind::Int: {
        if (a.kind != Arg::Kind::Integer) wrong(describe(p.group));
        // Every GX_* name in the expression must be of the parameter's group.
        std::istringstream parts(a.text);
        for (std::string w; parts >> w;) {
          if (w == "|" || w.rfind("GX_", 0) != 0) continue;
          const GxName* n = find_gx_name(w);
          if (n && n->group != p.group)
            fail_arg(k, w + " is " + describe(n->group) + ", expected " + describe(p.group));
        }
        if (a.value < p.min || a.value > p.max)
          fail_arg(k, "value out of range: " + a.text + " (" + std::to_string(p.min) + ".." +
                          std::to_string(p.max) + ")");
        break;
      }
      case ParamKind::F32:
        if (a.kind != Arg::Kind::Number && a.kind != Arg::Kind::Integer) wrong("a number");
        if (!std::isfinite(static_cast<float>(a.number)))
          fail_arg(k, "number out of float range: " + a.text);
        break;
      case ParamKind::Color:
      case ParamKind::ColorS10: {
        const bool s10 = p.kind == ParamKind::ColorS10;
        if (a.kind != (s10 ? Arg::Kind::ColorS10 : Arg::Kind::Color))
          wrong(s10 ? "a (GXColorS10){r, g, b, a}" : "a (GXColor){r, g, b, a}");
        const long long lo = s10 ? -1024 : 0, hi = s10 ? 1023 : 255;
        for (long long v : a.color) {
          if (v < lo || v > hi)
            fail_arg(k, "colour component out of range: " + std::to_string(v) + " (" +
                            std::to_string(lo) + ".." + std::to_string(hi) + ")");
        }
        break;
      }
      case ParamKind::LightRef:
        if (a.kind != Arg::Kind::AddressOf || !lights_.count(a.name))
          wrong("&name of a declared GXLightObj");
        break;
      case ParamKind::TexRef:
        if (a.kind != Arg::Kind::AddressOf || !textures_.count(a.name))
          wrong("&name of a declared GXTexObj");
        break;
      case ParamKind::TlutRef:
        if (a.kind != Arg::Kind::AddressOf || !tluts_.count(a.name))
          wrong("&name of a declared GXTlutObj");
        break;
      case ParamKind::TplRef:
        if (a.kind != Arg::Kind::AddressOf || !tpls_.count(a.name))
          wrong("&name of a declared TPLFile");
        break;
      case ParamKind::String:
        if (a.kind != Arg::Kind::String) wrong("a \"file name\"");
        break;
      case ParamKind::MtxName:
        if (a.kind != Arg::Kind::Identifier || !matrices_.count(a.name))
          wrong("the name of a declared Mtx");
        break;
      case ParamKind::MeshArray:
        if (a.kind != Arg::Kind::Identifier) wrong("the name of the attribute's array");
        break;
      case ParamKind::ArrayName:
        if (a.kind != Arg::Kind::Identifier || !arrays_.count(a.name))
          wrong("the name of a declared u8 array");
        break;
    }
  }

  const std::string& file_;
  const Call* call_ = nullptr;
  std::map<std::string, LightObject> lights_;
  std::map<std::string, TexObject> textures_;
  std::map<std::string, TlutObject> tluts_;
  std::map<std::string, TplObject> tpls_;
  std::map<std::string, TexMatrix> matrices_;
  std::map<std::string, std::vector<u8>> arrays_;
};

using Handler = std::function<void(Machine&)>;
struct CallInfo {
  std::vector<Param> params;
  Handler apply;
};
// Index of a colour channel argument: GX_COLOR0, GX_ALPHA0, GX_COLOR0A0 -> 0; the *1 -> 1.
inline int channel_index(long long channel) {
  return (channel == 1 || channel == 3 || channel == 5) ? 1 : 0;
}

using CallTable = std::map<std::string, CallInfo>;

// Each unit's calls, as libogc declares them.
void add_xf_calls(CallTable& table);     // channels, lights, texgen
void add_tev_calls(CallTable& table);    // TEV stages, registers, konst, swap tables
void add_pixel_calls(CallTable& table);  // pixel engine, textures, vertex format, cache
void add_tpl_calls(CallTable& table);    // TPL files (libogc's tpl.h)

}  // namespace lt::gx::interp
