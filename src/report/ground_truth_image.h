// Where the bench writes a scene's ground-truth render, named by the registry's ground-truth path
// (PathRole::GroundTruth), so the images, the contact sheet and the page's flip agree with the
// registry and with each other.
#pragma once

#include <string>

namespace lt {

// "images/SCENE__reference.png" for extension ".png": relative to the bench's output folder.
std::string ground_truth_image(const std::string& scene, const std::string& extension);
// The ground-truth path's name ("reference"), the label the page flips to.
const std::string& ground_truth_label();

}  // namespace lt
