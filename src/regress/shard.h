// `--shard I/N`: a deterministic partition of the case list for a CI matrix. Shard I of N (1 <= I
// <= N, as GitLab's CI_NODE_INDEX/CI_NODE_TOTAL count) takes the cases at positions I-1, I-1+N,
// I-1+2N, ... of the ordered list: every case is in exactly one shard, the shards' sizes differ by
// at most one, and the same inputs give the same shards on every runner.
#pragma once

#include <cstddef>
#include <string>

namespace lt {

struct Shard {
  int index = 1, count = 1;

  bool takes(size_t position) const {
    return static_cast<int>(position % static_cast<size_t>(count)) == index - 1;
  }
  std::string to_string() const { return std::to_string(index) + "/" + std::to_string(count); }
};

// "I/N" with 1 <= I <= N <= 10000; throws InputError naming --shard otherwise.
Shard parse_shard(const std::string& text);

}  // namespace lt
