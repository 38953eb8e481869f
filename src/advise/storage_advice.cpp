#include "advise/storage_advice.h"

#include <algorithm>
#include <map>
#include <optional>

#include "advise/advise.h"
#include "advise/material_error.h"
#include "core/error.h"
#include "render/evaluate.h"
#include "render/session.h"

namespace lt::advise {

namespace {

// The pick's variant with a storage's keys after it ("" keeps it as it is).
std::string with_storage(const std::string& variant, const std::string& storage) {
  return storage.empty() ? variant : variant + ":" + storage;
}

}  // namespace

void add_storage_advice(Advice& a, const Scene& scene, const PathInfo& path,
                        const PathOptions& options, const std::string& profile) {
  if (!path.writes_fifo_log) return;
  const bool any_pick = std::any_of(a.materials.begin(), a.materials.end(),
                                    [](const MaterialAdvice& ma) { return ma.pick.has_value(); });
  if (!any_pick) return;
  RenderSession session(scene, a.width, a.height);
  const Image reference = render_reference(session);
  const std::vector<int> material_of_pixel = material_per_pixel(session.context());
  // Each variant measured once: its bytes, or why the mesh does not fit it, and the image.
  struct Measured {
    std::string failed;
    ConsoleBytes bytes;
    Image image;
    TestEncoding encoding{};
  };
  std::map<std::string, Measured> measured;
  auto measure = [&](const std::string& variant) -> const Measured& {
    if (auto it = measured.find(variant); it != measured.end()) return it->second;
    Measured m;
    const std::optional<ConsoleBytes> bytes = console_bytes(path.budget(scene, variant, profile));
    if (!bytes) {
      m.failed = "the scene's mesh does not fit this storage (`ltrender budget --path " +
                 path.name + " --variant " + variant + "` says why)";
    } else if (std::string refused = path.refusal(scene, variant); !refused.empty()) {
      m.failed = refused;
    } else {
      m.bytes = *bytes;
      auto built = session.build(path, variant, options);
      built->frame();
      m.image = built->result();
      m.encoding = test_encoding(*built);
    }
    return measured.emplace(variant, std::move(m)).first->second;
  };
  for (MaterialAdvice& ma : a.materials) {
    if (!ma.pick) continue;
    const std::string& picked = a.candidates[*ma.pick].candidate.variant;
    StorageAdvice advice;
    for (const char* storage : kStorages) {
      StorageOption o;
      o.storage = storage;
      o.variant = with_storage(picked, storage);
      const Measured& m = measure(o.variant);
      o.failed = m.failed;
      if (o.failed.empty()) {
        o.bytes = m.bytes;
        const Comparison c = compare_material(m.image, reference, m.encoding, material_of_pixel,
                                              static_cast<int>(ma.index));
        o.error = c.covered;
        o.non_finite = non_finite_pixels(c);
      }
      const bool within = o.failed.empty() && o.non_finite == 0 &&
                          stat_of(o.error, a.options.stat) <= a.options.max_lsb;
      if (within &&
          (!advice.pick || o.bytes.fifo_bytes < advice.options[*advice.pick].bytes.fifo_bytes))
        advice.pick = advice.options.size();
      advice.options.push_back(std::move(o));
    }
    ma.storage = std::move(advice);
  }
}

}  // namespace lt::advise
