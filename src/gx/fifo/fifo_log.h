// A Dolphin FIFO log (.dff, file version 5): what Dolphin's FIFO player plays. The container is
// little endian and packed [DHW Core/FifoPlayer/FifoDataFile.cpp FileHeader, FileFrameInfo,
// FileMemoryUpdate]: a 128-byte header; one 64-byte record per frame; the BP (256 u32), CP
// (256 u32), XF memory (4096 u32) and XF register (88 u32) snapshots the player loads before
// the first frame; 1 MiB of TMEM; then per frame its FIFO bytes (the big-endian GP command
// stream) and its memory updates (24-byte records, then their data) - RAM the player writes
// when its FIFO reaches the update's position, on every replay.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "gx/fifo/command_stream.h"

namespace lt::gx::fifo {

inline constexpr u32 kFifoLogId = 0x0d01f1f0, kFifoLogVersion = 5, kMinLoaderVersion = 1;
inline constexpr size_t kTmemBytes = 1024 * 1024;
// The Wii's retail RAM sizes: a log must give them or the player mismaps memory
// [DHW FifoDataFile.cpp mem1_size / mem2_size, PR#8722].
inline constexpr u32 kMem1Size = 0x01800000, kMem2Size = 0x04000000;
// The GP FIFO ring the frame says it was recorded from (fifoStart / fifoEnd: the last 32-byte
// line), clear of every address the frame writes (frame_recording.h's memory map).
inline constexpr u32 kFifoRingStart = 0x01000000, kFifoRingEnd = 0x0103ffe0;

// FifoDataFile.h MemoryUpdate::Type: TEXTURE_MAP 1, XF_DATA 2, VERTEX_STREAM 4, TMEM 8.
inline constexpr u8 kMemoryUpdateTexture = 0x01, kMemoryUpdateTmem = 0x08;  // TMEM: a TLUT

struct MemoryUpdate {
  u32 fifo_position = 0;  // byte offset into the frame's FIFO data
  u32 address = 0;        // physical RAM address
  u8 type = kMemoryUpdateTexture;
  std::vector<u8> data;
  bool operator==(const MemoryUpdate&) const = default;
};

struct FifoFrame {
  std::vector<u8> fifo;
  std::vector<MemoryUpdate> updates;  // in FIFO order
  bool operator==(const FifoFrame&) const = default;
};

struct FifoLog {
  std::array<u32, kBpRegisters> bp{};
  std::array<u32, kCpRegisters> cp{};
  std::array<u32, kXfMemoryWords> xf_memory{};
  std::array<u32, kXfRegisters> xf_registers{};
  // Header flag bit 0 [DHW FifoDataFile.h FLAG_IS_WII]. Off: the GX of the Wii is the
  // GameCube's, and Dolphin plays a GameCube log at 4:3 - a Wii log takes the emulated Wii's
  // 16:9 display setting and its dump is stretched (measured: a 320 x 240 frame dumps as
  // 424 x 240).
  bool wii = false;
  std::vector<FifoFrame> frames;
  bool operator==(const FifoLog&) const = default;
};

std::vector<u8> write_fifo_log(const FifoLog& log);
// Reads a log written by any writer of version 5 (or earlier: the header is the same size).
// Throws InputError(`file`, key, ...) naming what is malformed.
FifoLog read_fifo_log(const std::vector<u8>& bytes, const std::string& file);

}  // namespace lt::gx::fifo
