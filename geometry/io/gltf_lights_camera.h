#pragma once
// KHR_lights_punctual lights and perspective cameras of a glTF document as
// umbra's Light and Camera (docs/scene-format.md, "glTF scenes"): the
// fields, their ranges, and umbra's `extras.umbra` (a light's falloff, a
// camera's image size). Where they stand comes from their node
// (gltf_scene.cpp). Internal to geometry/io.
#include <umbra/geometry/io/gltf_document.h>
#include <umbra/geometry/io/gltf_matrix.h>
#include <umbra/geometry/scene.h>

#include <string>

namespace umbra::geometry::gltf {

/// The light `v` (at `path`, an element of the extension's `lights` array),
/// unplaced: a point light's position and a directional light's direction
/// are its node's to give.
Light read_light(const Document& doc, const tinygltf::Value& v, const std::string& path);

/// The perspective camera `gltf` (at `path`) placed by its node's world
/// matrix: a glTF camera looks down its local -Z with +Y up.
Camera make_camera(const Document& doc, const tinygltf::Camera& gltf, const std::string& path,
                   const Matrix& world);

}  // namespace umbra::geometry::gltf
