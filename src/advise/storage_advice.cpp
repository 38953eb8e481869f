#include "advise/storage_advice.h"

#include <algorithm>
#include <map>
#include <optional>

#include "advise/advise.h"
#include "advise/material_error.h"
#include "advise/variant_trials.h"
#include "core/error.h"

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
  if (!has_any_pick(a)) return;
  VariantTrials trials(scene, path, options, profile, a.width, a.height);
  for (MaterialAdvice& ma : a.materials) {
    if (!ma.pick) continue;
    const std::string& picked = a.candidates[*ma.pick].candidate.variant;
    StorageAdvice advice;
    for (const char* storage : kStorages) {
      StorageOption o;
      o.storage = storage;
      o.variant = with_storage(picked, storage);
      // A storage the scene's mesh does not fit has no console bytes.
      const VariantTrials::Trial& t =
          trials.trial(o.variant, [&](const budget::Report& report) -> std::string {
            if (console_bytes(report)) return "";
            return "the scene's mesh does not fit this storage (`ltrender budget --path " +
                   path.name + " --variant " + o.variant + "` says why)";
          });
      o.failed = t.failed;
      if (o.failed.empty()) {
        o.bytes = *console_bytes(t.budget);
        const Comparison c = trials.compare(t, ma.index);
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
