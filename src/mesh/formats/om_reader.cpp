#include "mesh/formats/om_reader.h"

#include <cstdint>
#include <cstring>

#include "core/error.h"
#include "core/sandboxed_child.h"
#include "mesh/reader_support.h"

namespace lt::meshio {

using OpenMesh::IO::Options;

namespace {

RawMesh faces_of_om_mesh(const PolyMesh& raw, const Options& options, const std::string& file) {
  RawMesh out;
  out.binary = options.is_binary();
  const std::size_t nv = raw.n_vertices(), nh = raw.n_halfedges();
  for (auto vh : raw.vertices()) {
    const auto& p = raw.point(vh);
    out.positions.emplace_back(p[0], p[1], p[2]);
    if (options.vertex_has_normal()) out.normals.push_back(to_glm(raw.normal(vh)));
    if (options.vertex_has_color()) {
      const auto& c = raw.color(vh);
      out.colors.emplace_back(c[0], c[1], c[2]);
    }
    if (options.vertex_has_texcoord()) out.uvs.push_back(to_glm(raw.texcoord2D(vh)));
  }
  auto corrupt = [&](std::size_t f) {
    fail(file, 0, "face " + std::to_string(f) + " has a broken halfedge loop (corrupt OM file)");
  };
  for (std::size_t f = 0; f < raw.n_faces(); ++f) {
    const auto start = raw.halfedge_handle(OpenMesh::FaceHandle(static_cast<int>(f)));
    if (start.idx() < 0 || static_cast<std::size_t>(start.idx()) >= nh) corrupt(f);
    auto h = start;
    std::size_t steps = 0;
    do {
      const auto v = raw.to_vertex_handle(h);
      if (v.idx() < 0 || static_cast<std::size_t>(v.idx()) >= nv) corrupt(f);
      out.face_indices.push_back(static_cast<std::uint32_t>(v.idx()));
      h = raw.next_halfedge_handle(h);
      if (h.idx() < 0 || static_cast<std::size_t>(h.idx()) >= nh || ++steps > nh) corrupt(f);
    } while (h != start);
    if (steps < 3) corrupt(f);
    out.face_offsets.push_back(static_cast<std::uint32_t>(out.face_indices.size()));
  }
  return out;
}

// RawMesh over the pipe: counts, then the arrays as they are in memory (same process image).
std::string serialize(const RawMesh& m) {
  std::string out;
  auto put = [&out](const void* p, std::size_t n) {
    if (n) out.append(static_cast<const char*>(p), n);
  };
  const std::uint64_t counts[6] = {m.positions.size(),    m.normals.size(),
                                   m.colors.size(),       m.uvs.size(),
                                   m.face_offsets.size(), m.face_indices.size()};
  put(counts, sizeof counts);
  const char binary = m.binary ? 1 : 0;
  put(&binary, 1);
  put(m.positions.data(), m.positions.size() * sizeof(glm::dvec3));
  put(m.normals.data(), m.normals.size() * sizeof(glm::dvec3));
  put(m.colors.data(), m.colors.size() * sizeof(glm::vec3));
  put(m.uvs.data(), m.uvs.size() * sizeof(glm::dvec2));
  put(m.face_offsets.data(), m.face_offsets.size() * sizeof(std::uint32_t));
  put(m.face_indices.data(), m.face_indices.size() * sizeof(std::uint32_t));
  return out;
}

// Checks sizes and indices: the child's memory may have been damaged by the file it read.
RawMesh deserialize(const std::string& data, const std::string& file) {
  auto broken = [&]() {
    fail(file, 0, "OpenMesh's OM reader returned an inconsistent mesh (corrupt file?)");
  };
  std::uint64_t counts[6];
  if (data.size() < sizeof counts + 1) broken();
  std::memcpy(counts, data.data(), sizeof counts);
  const auto [nv, nn, nc, nu, no, ni] = counts;
  if (nv > (1u << 31) || (nn != 0 && nn != nv) || (nc != 0 && nc != nv) || (nu != 0 && nu != nv) ||
      no < 1 || no > (1u << 31) || ni > (1ull << 34))
    broken();
  const std::size_t expected = sizeof counts + 1 + (nv + nn) * sizeof(glm::dvec3) +
                               nc * sizeof(glm::vec3) + nu * sizeof(glm::dvec2) +
                               (no + ni) * sizeof(std::uint32_t);
  if (data.size() != expected) broken();
  RawMesh m;
  std::size_t pos = sizeof counts;
  m.binary = data[pos++] != 0;
  auto get = [&](auto& vec, std::size_t n) {
    vec.resize(n);
    if (n) std::memcpy(vec.data(), data.data() + pos, n * sizeof(vec[0]));
    pos += n * sizeof(vec[0]);
  };
  get(m.positions, nv);
  get(m.normals, nn);
  get(m.colors, nc);
  get(m.uvs, nu);
  get(m.face_offsets, no);
  get(m.face_indices, ni);
  if (m.face_offsets.front() != 0 || m.face_offsets.back() != ni) broken();
  for (std::size_t f = 0; f + 1 < no; ++f) {
    if (m.face_offsets[f + 1] < m.face_offsets[f] + 3) broken();
  }
  for (auto i : m.face_indices) {
    if (i >= nv) broken();
  }
  return m;
}

}  // namespace

RawMesh read_om_in_child(const std::filesystem::path& path, const std::string& file,
                         OpenMeshLogCapture& capture) {
  std::error_code ec;
  const std::uintmax_t file_size = std::filesystem::file_size(path, ec);
  const std::size_t size = ec ? 0 : static_cast<std::size_t>(file_size);
  SandboxLimits limits;
  limits.address_space_budget = (std::size_t{512} << 20) + 64 * size;
  // OM reads at well over 100 MB/s; 2 s per MB is a generous bound before calling it a hang.
  limits.time_limit = std::chrono::seconds(10 + static_cast<long long>(size >> 19));
  const SandboxOutcome got = run_in_sandboxed_child(limits, [&](std::string& payload) {
    try {
      PolyMesh raw;
      Options options = requested_options();
      // The log streams still point into the parent's capture buffer, copied by fork.
      read_with_openmesh(raw, file, options, capture);
      payload = serialize(faces_of_om_mesh(raw, options, file));
      return 0;
    } catch (const InputError& e) {
      payload = e.what_only();
    } catch (const std::exception& e) {
      payload = std::string("OpenMesh could not read it: ") + e.what();
    }
    return kSandboxWorkThrew;
  });
  switch (got.end) {
    case SandboxOutcome::End::NotStarted:
      fail(file, 0, "cannot read OM files: " + got.payload);
    case SandboxOutcome::End::TimedOut:
      fail(file, 0, "OpenMesh's OM reader did not finish reading this file (corrupt?)");
    case SandboxOutcome::End::Signalled:
      fail(file, 0,
           "OpenMesh's OM reader crashed on this file (signal " + std::to_string(got.code) +
               "; corrupt or truncated?)");
    case SandboxOutcome::End::SanitizerDied:
      fail(file, 0,
           "OpenMesh's OM reader crashed on this file (sanitizer report; corrupt or truncated?)");
    case SandboxOutcome::End::Exited:
      break;
  }
  if (got.code != 0)
    fail(file, 0, got.payload.empty() ? "OpenMesh could not read it" : got.payload);
  return deserialize(got.payload, file);
}

}  // namespace lt::meshio
