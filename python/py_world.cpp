// plantsim.World: the plant's rectangles and poses; plantsim.load_world for every format.
#include "python/py_world.h"

#include <pybind11/stl.h>

#include "worlds/world_fingerprint.h"
#include "worlds/world_loader.h"

namespace plantsim::python {
namespace {

py::array_t<double> rects_array(const std::vector<geom::Rect>& rects) {
  py::array_t<double> a({static_cast<py::ssize_t>(rects.size()), py::ssize_t{4}});
  auto v = a.mutable_unchecked<2>();
  for (std::size_t i = 0; i < rects.size(); ++i) {
    const auto k = static_cast<py::ssize_t>(i);
    v(k, 0) = rects[i].xmin, v(k, 1) = rects[i].ymin, v(k, 2) = rects[i].xmax,
         v(k, 3) = rects[i].ymax;
  }
  return a;
}

PyWorld load(const py::object& path_arg, const py::object& start, const py::object& charger,
             const std::string& scen, int query) {
  const std::string path =
      py::str(py::module_::import("os").attr("fspath")(path_arg)).cast<std::string>();
  worlds::PoseOverrides overrides;
  if (!start.is_none()) overrides.start = pose_from(start, "start");
  if (!charger.is_none()) overrides.charger = pose_from(charger, "charger");
  overrides.movingai_scen = scen;
  if (query < 0) throw std::invalid_argument("query must be 0 or more");
  overrides.movingai_query = query;
  return {std::make_shared<const worlds::World>(worlds::load_world(path, overrides))};
}

}  // namespace

PyWorld world_argument(const py::handle& value) {
  if (py::isinstance<PyWorld>(value)) return value.cast<PyWorld>();
  if (py::isinstance<py::str>(value) || py::hasattr(value, "__fspath__"))
    return load(py::reinterpret_borrow<py::object>(value), py::none(), py::none(), "", 0);
  throw std::invalid_argument("world must be a plantsim.World or the path of a world file");
}

void bind_world(py::module_& m) {
  py::class_<PyWorld>(
      m, "World", "A plant: floor, rectangles, start and charger poses, robot (SI units, y up).")
      .def_property_readonly("name", [](const PyWorld& w) { return w.world->name; })
      .def_property_readonly(
          "source", [](const PyWorld& w) { return w.world->source; }, "the file it was loaded from")
      .def_property_readonly(
          "floor",
          [](const PyWorld& w) { return rects_array({w.world->floor}).attr("reshape")(4); },
          "[xmin, ymin, xmax, ymax] of the floor (its boundary is a wall)")
      .def_property_readonly(
          "obstacles", [](const PyWorld& w) { return rects_array(w.world->obstacles); },
          "N x 4 array of mapped rectangles [xmin, ymin, xmax, ymax]")
      .def_property_readonly(
          "unmapped", [](const PyWorld& w) { return rects_array(w.world->unmapped); },
          "rectangles in the plant but not on the robot's map")
      .def_property_readonly(
          "start", [](const PyWorld& w) { return pose_array(w.world->start); }, "[x, y, yaw]")
      .def_property_readonly(
          "charger", [](const PyWorld& w) { return pose_array(w.world->charger); },
          "the docked pose [x, y, yaw]")
      .def_property_readonly(
          "staging", [](const PyWorld& w) { return pose_array(worlds::staging_pose(*w.world)); },
          "the staging pose in front of the charger, where docking begins")
      .def_property_readonly("robot_radius",
                             [](const PyWorld& w) { return w.world->robot.radius_m; })
      .def_property_readonly("wheel_base",
                             [](const PyWorld& w) { return w.world->robot.wheel_base_m; })
      .def_property_readonly("max_speed",
                             [](const PyWorld& w) { return w.world->robot.max_speed_mps; })
      .def("__repr__",
           [](const PyWorld& w) {
             return "<plantsim.World '" + w.world->name +
                    "': " + std::to_string(w.world->obstacles.size()) + " rectangles>";
           })
      // Pickled as its file, poses and content fingerprint (for multiprocessing): loaded again
      // on the other side, refused if the file no longer holds the same world.
      .def(py::pickle(
          [](const PyWorld& w) {
            return py::make_tuple(w.world->source, pose_array(w.world->start),
                                  pose_array(w.world->charger),
                                  worlds::world_fingerprint(*w.world));
          },
          [](const py::tuple& t) {
            if (t.size() != 4) throw std::invalid_argument("not a pickled plantsim.World");
            const PyWorld w = load(t[0], t[1], t[2], "", 0);
            if (worlds::world_fingerprint(*w.world) != t[3].cast<std::uint64_t>())
              throw std::invalid_argument(w.world->source +
                                          ": the file no longer holds the pickled world");
            return w;
          }));
  m.def(
      "load_world", &load, py::arg("path"), py::kw_only(), py::arg("start") = py::none(),
      py::arg("charger") = py::none(), py::arg("scen") = "", py::arg("query") = 0,
      R"(Loads a world: plantsim JSON, a plain benchmark world, a ROS map_server YAML or a MovingAI .map.

start, charger: (x, y, yaw) overriding the file's poses. scen, query: for a MovingAI map, the
.scen file and the query number that give the start and the charger. Raises plantsim.InputError
naming the file and the field, as `plantsim run` does.)");
}

}  // namespace plantsim::python
