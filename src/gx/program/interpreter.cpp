#include "gx/program/interpreter.h"

#include "gx/program/machine.h"

namespace lt::gx {

namespace interp {

namespace {

const CallTable& calls() {
  static const CallTable table = [] {
    CallTable t;
    add_xf_calls(t);
    add_tev_calls(t);
    add_pixel_calls(t);
    add_tpl_calls(t);
    return t;
  }();
  return table;
}

}  // namespace

void Machine::execute(const Call& c) {
  call_ = &c;
  const auto& table = calls();
  const auto it = table.find(c.function);
  if (it == table.end()) {
    static const std::map<std::string, std::string> not_modelled = {
        {"GX_LoadPosMtxImm", "matrices come from the scene's camera"},
        {"GX_LoadNrmMtxImm", "matrices come from the scene's camera"},
        {"GX_SetCurrentMtx", "matrices come from the scene's camera"},
        {"GX_Begin", "geometry comes from the scene"},
    };
    const auto nm = not_modelled.find(c.function);
    if (nm != not_modelled.end()) fail(c.pos, c.function + ": not modelled: " + nm->second);
    fail(c.pos, c.function.rfind("GX_", 0) == 0
                    ? c.function + ": not modelled by the emulator (see `ltrender render --help`)"
                    : "unknown call " + c.function);
  }
  const CallInfo& info = it->second;
  if (c.args.size() != info.params.size())
    fail(c.pos, c.function + ": expected " + std::to_string(info.params.size()) +
                    " arguments, found " + std::to_string(c.args.size()));
  for (size_t k = 0; k < c.args.size(); ++k) check_arg(k, info.params[k]);
  info.apply(*this);
}

}  // namespace interp

GxState run_program(const std::string& file,
                    const std::vector<const std::vector<Statement>*>& blocks) {
  interp::Machine m(file);
  for (const auto* block : blocks) m.run(*block);
  return m.state;
}

}  // namespace lt::gx
