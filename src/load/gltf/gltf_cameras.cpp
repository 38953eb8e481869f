#include "load/gltf/gltf_cameras.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/error.h"
#include "load/gltf/gltf_importer.h"
#include "load/gltf/gltf_scene.h"
#include "scene/scene_limits.h"

namespace lt::gltf {

namespace {

using json = nlohmann::json;

// A camera's far plane when zfar is absent (an infinite projection, glTF 2.0 §3.10.3): this many
// times znear, which keeps a 24-bit depth buffer usable.
constexpr double kInfiniteFarOverNear = 1e5;

bool camera_named(const Document& doc, const CameraInstance& c, const std::string& name) {
  return doc.model.cameras[static_cast<std::size_t>(c.camera)].name == name ||
         doc.model.nodes[static_cast<std::size_t>(c.node)].name == name;
}

// How `--camera` can name a camera the scene places: its name, else its node's, else #N.
std::string camera_label(const Document& doc, const CameraInstance& c) {
  const std::string& name = doc.model.cameras[static_cast<std::size_t>(c.camera)].name;
  if (!name.empty()) return name;
  const std::string& node = doc.model.nodes[static_cast<std::size_t>(c.node)].name;
  if (!node.empty()) return node;
  std::string index = "#";  // appended, not "#" + ...: GCC 12 warns falsely (-Wrestrict) on that
  return index += std::to_string(c.camera);
}

}  // namespace

void camera_from(const Document& doc, const CameraInstance& inst, Scene& scene) {
  const tinygltf::Camera& cam = doc.model.cameras[static_cast<std::size_t>(inst.camera)];
  const std::string ptr = "/cameras/" + std::to_string(inst.camera);
  Camera& c = scene.camera;
  // §3.10.1: a camera looks down its node's -Z with +Y up.
  c.eye = glm::dvec3(inst.world * glm::dvec4(0, 0, 0, 1));
  check_world_point(doc, "/nodes/" + std::to_string(inst.node), c.eye, "its camera");
  c.target = c.eye + glm::normalize(glm::dvec3(inst.world * glm::dvec4(0, 0, -1, 0)));
  c.up = glm::dvec3(inst.world * glm::dvec4(0, 1, 0, 0));
  if (cam.type == "perspective") {
    c.projection = Camera::Projection::Perspective;
    c.fov_y_deg = cam.perspective.yfov * 180 / M_PI;
    c.near = cam.perspective.znear;
    c.far = cam.perspective.zfar > 0 ? cam.perspective.zfar : c.near * kInfiniteFarOverNear;
    if (!(c.fov_y_deg >= 1e-3 && c.fov_y_deg <= 179))
      doc.fail(ptr + "/perspective/yfov", "out of range (0.001 to 179 degrees)");
    if (!(c.near > 0)) doc.fail(ptr + "/perspective/znear", "must be > 0");
    if (cam.perspective.aspectRatio > 0) {
      scene.width = static_cast<int>(
          std::clamp(std::round(kDefaultHeight * cam.perspective.aspectRatio), 1.0, kMaxImageSide));
    }
    scene.import_notes.push_back(
        "mapped " + ptr + " (perspective, node " + std::to_string(inst.node) + ") -> fov_y_deg " +
        json(c.fov_y_deg).dump() + ", near " + json(c.near).dump() + ", far " + json(c.far).dump() +
        (cam.perspective.zfar > 0 ? "" : " (no zfar: near x 1e5)") + ", image " +
        std::to_string(scene.width) + "x" + std::to_string(scene.height));
  } else {
    c.projection = Camera::Projection::Orthographic;
    // §3.10.3: ymag is half the orthographic view's height.
    c.height = 2 * cam.orthographic.ymag;
    c.near = cam.orthographic.znear;
    c.far = cam.orthographic.zfar;
    if (!(c.height > 0)) doc.fail(ptr + "/orthographic/ymag", "must be > 0");
    scene.import_notes.push_back("mapped " + ptr + " (orthographic, node " +
                                 std::to_string(inst.node) + ") -> height " +
                                 json(c.height).dump() + " (2 x ymag), near " +
                                 json(c.near).dump() + ", far " + json(c.far).dump());
    scene.import_notes.push_back("ignored " + ptr +
                                 "/orthographic/xmag: the image's aspect sets the width");
  }
  if (!(c.far > c.near)) doc.fail(ptr, "zfar must be greater than znear");
  if (!(glm::length(glm::cross(c.forward(), c.up)) > 1e-9))
    doc.fail("/nodes/" + std::to_string(inst.node), "its transform collapses the camera's axes");
}

void framing_camera(Scene& scene) {
  glm::dvec3 lo(std::numeric_limits<double>::max()), hi(-std::numeric_limits<double>::max());
  for (const SceneObject& o : scene.objects) {
    for (const glm::dvec3& p : o.mesh.positions) lo = glm::min(lo, p), hi = glm::max(hi, p);
  }
  if (scene.objects.empty() || lo.x > hi.x) lo = hi = glm::dvec3(0);
  const glm::dvec3 centre = (lo + hi) * 0.5;
  const double radius = std::max(glm::length(hi - lo) * 0.5, 1e-3);
  Camera& c = scene.camera;
  const double distance = radius / std::sin(glm::radians(c.fov_y_deg) * 0.5);
  c.target = centre;
  c.eye = centre + glm::dvec3(0, 0, distance);
  c.near = std::max(distance - radius, distance * 1e-3);
  c.far = distance + radius * 2;
  scene.import_notes.push_back(
      "default camera: no camera in the file, framing the meshes from +Z (eye " +
      json({c.eye.x, c.eye.y, c.eye.z}).dump() + ")");
}

const CameraInstance& chosen_camera(const Document& doc, const std::vector<CameraInstance>& cameras,
                                    const std::string& wanted) {
  auto it = std::find_if(cameras.begin(), cameras.end(),
                         [&](const CameraInstance& c) { return camera_named(doc, c, wanted); });
  const int index = hash_index(wanted);
  if (it == cameras.end() && index >= 0)
    it = std::find_if(cameras.begin(), cameras.end(),
                      [&](const CameraInstance& c) { return c.camera == index; });
  if (it != cameras.end()) return *it;
  std::string labels;
  for (const CameraInstance& c : cameras)
    labels += (labels.empty() ? "" : ", ") + camera_label(doc, c);
  throw InputError("--camera", wanted,
                   "no camera of that name or index (#N: /cameras/N) on a node of the scene in " +
                       doc.path.string() + " (cameras: " + (labels.empty() ? "none" : labels) +
                       ")");
}

}  // namespace lt::gltf
