#include "mesh_arrays.h"

#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include "matgeom/mesh.h"

namespace matpredict_python {
namespace {

namespace py = pybind11;

// An (N, columns) array of `Scalar`, converted (a float64 array of positions is fine).
template <class Scalar>
py::array_t<Scalar, py::array::c_style | py::array::forcecast> table(const py::array& array, py::ssize_t columns,
                                                                    const std::string& name) {
  const char kind = array.dtype().kind();
  const bool numeric = kind == 'f' || kind == 'i' || kind == 'u';
  if (!numeric || (std::is_integral_v<Scalar> && kind == 'f'))
    throw py::type_error(name + ": expected an array of " + (std::is_integral_v<Scalar> ? "integers" : "numbers") +
                         ", got dtype " + std::string(py::str(array.dtype())));
  if (array.ndim() != (columns == 1 ? 1 : 2) || (columns > 1 && array.shape(1) != columns))
    throw py::value_error(name + ": expected shape (N" + (columns > 1 ? ", " + std::to_string(columns) : std::string(",")) + ")");
  return py::array_t<Scalar, py::array::c_style | py::array::forcecast>::ensure(array);
}

MeshArrays make_mesh(const py::array& positions, const py::array& triangles, const std::optional<py::array>& uvs,
                     const std::optional<py::array>& normals, const std::optional<py::array>& parts,
                     const std::optional<std::vector<std::string>>& part_names) {
  auto asset = std::make_shared<matgeom::ObjectAsset>();
  matgeom::TriangleMesh& mesh = asset->mesh;
  const auto p = table<float>(positions, 3, "positions");
  for (py::ssize_t v = 0; v < p.shape(0); ++v) mesh.positions.emplace_back(p.at(v, 0), p.at(v, 1), p.at(v, 2));
  const auto t = table<int64_t>(triangles, 3, "triangles");
  for (py::ssize_t k = 0; k < t.shape(0); ++k) {
    for (int c = 0; c < 3; ++c)
      if (t.at(k, c) < 0 || t.at(k, c) >= p.shape(0))
        throw py::value_error("triangles: triangle " + std::to_string(k) + " names vertex " + std::to_string(t.at(k, c)) +
                              ", not one of the " + std::to_string(p.shape(0)) + " positions");
    mesh.triangles.emplace_back(t.at(k, 0), t.at(k, 1), t.at(k, 2));
  }
  if (uvs) {
    const auto u = table<float>(*uvs, 2, "uvs");
    for (py::ssize_t v = 0; v < u.shape(0); ++v) mesh.uvs.emplace_back(u.at(v, 0), u.at(v, 1));
  }
  if (normals) {
    const auto n = table<float>(*normals, 3, "normals");
    for (py::ssize_t v = 0; v < n.shape(0); ++v) mesh.normals.emplace_back(n.at(v, 0), n.at(v, 1), n.at(v, 2));
  }
  if (parts) {
    const auto part = table<int64_t>(*parts, 1, "parts");
    for (py::ssize_t k = 0; k < part.shape(0); ++k) {
      if (part.at(k) < 0) throw py::value_error("parts: triangle " + std::to_string(k) + " has a negative part");
      mesh.triangle_parts.push_back(static_cast<uint32_t>(part.at(k)));
    }
  }
  const uint32_t part_count = mesh.part_count();
  if (part_names && part_names->size() != part_count)
    throw py::value_error("part_names: expected " + std::to_string(part_count) + " names, one per part, got " +
                          std::to_string(part_names->size()));
  for (uint32_t k = 0; k < part_count; ++k) mesh.part_names.push_back(part_names ? (*part_names)[k] : "part" + std::to_string(k));
  asset->materials.resize(part_count);
  try {
    matgeom::validate_mesh(mesh, "mesh");
  } catch (const std::invalid_argument& e) {
    throw py::value_error(e.what());
  }
  return MeshArrays{asset};
}

}  // namespace

void bind_mesh(py::module_& module) {
  py::class_<MeshArrays>(module, "Mesh",
                         "A triangle mesh from numpy arrays, for a scene dict's object: {\"mesh\": matpredict.Mesh(...)}.")
      .def(py::init(&make_mesh), py::arg("positions"), py::arg("triangles"), py::kw_only(), py::arg("uvs") = py::none(),
           py::arg("normals") = py::none(), py::arg("parts") = py::none(), py::arg("part_names") = py::none(),
           "positions (N, 3) in metres (Z up), triangles (M, 3) vertex indices counter-clockwise seen from\n"
           "outside; optional uvs (N, 2), normals (N, 3) for smooth shading, parts (M,) a part per triangle\n"
           "and part_names (one per part; 'part0', 'part1', ... by default), which an object's \"materials\"\n"
           "names. The arrays are copied and checked: a ValueError names what is wrong.")
      .def_property_readonly("vertex_count", [](const MeshArrays& m) { return m.asset->mesh.vertex_count(); },
                             "Vertices (rows of positions).")
      .def_property_readonly("triangle_count", [](const MeshArrays& m) { return m.asset->mesh.triangle_count(); },
                             "Triangles (rows of triangles).")
      .def_property_readonly("part_names", [](const MeshArrays& m) { return m.asset->mesh.part_names; },
                             "The parts' names, by part id: what an object's \"materials\" names.");
}

}  // namespace matpredict_python
