#include "report/ground_truth_image.h"

#include "paths/path.h"

namespace lt {

std::string ground_truth_image(const std::string& scene, const std::string& extension) {
  return "images/" + scene + "__" + ground_truth_label() + extension;
}

const std::string& ground_truth_label() { return path_with_role(PathRole::GroundTruth).name; }

}  // namespace lt
