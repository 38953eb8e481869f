// The arbfp path's fragment program for one state key (arb_key.h): the equation of model.md per
// pixel.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "arb/arb_ir.h"
#include "model/power_lut.h"
#include "paths/arbfp/arb_key.h"
#include "scene/scene.h"

namespace lt::arbfp {

// `lut` receives the power texture of pow=lut. `notes` holds the key's notes; the lobe method
// appends its own (sg-fitted's fit), and the program's header lists them all.
ir::Program fragment_program(const Key& k, const Material& material,
                             std::optional<model::PowerLut>& lut, std::vector<std::string>& notes);

}  // namespace lt::arbfp
