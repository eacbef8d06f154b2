// plantsim.World: the plant's rectangles and poses; plantsim.load_world for every format.
#include "python/py_world.h"

#include <pybind11/stl.h>

#include "worlds/names.h"
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

/// The world under another name (checked by the rule every name follows, worlds/names.h):
/// a copy, since plans and runs share the loaded one.
PyWorld renamed(const PyWorld& w, const std::string& name) {
  if (const std::string problem = worlds::name_problem(name); !problem.empty())
    throw std::invalid_argument("name: " + problem);
  auto copy = std::make_shared<worlds::World>(*w.world);
  copy->name = name;
  return {copy};
}

PyWorld load(const py::object& path_arg, const py::object& start, const py::object& charger,
             const std::string& scen, const py::object& query) {
  const std::string path = file_from(path_arg, "world");
  worlds::PoseOverrides overrides;
  if (!start.is_none()) overrides.start = pose_from(start, "start");
  if (!charger.is_none()) overrides.charger = pose_from(charger, "charger");
  overrides.movingai_scen = scen.empty() ? scen : file_from(py::str(scen), "scen");
  overrides.movingai_query = static_cast<int>(whole_from(query, "query", 0, 1 << 30));
  return {std::make_shared<const worlds::World>(worlds::load_world(path, overrides))};
}

/// The pickled state: what load() needs to read the world again, the fingerprint that proves
/// the file still holds it, and the fields a World may change after loading (its name).
py::tuple world_state(const PyWorld& w) {
  return py::make_tuple(w.world->source, pose_array(w.world->start), pose_array(w.world->charger),
                        worlds::world_fingerprint(*w.world), w.world->name);
}

PyWorld world_from_state(const py::tuple& t) {
  // 4 fields: pickled before the name was kept (the file's name then).
  if (t.size() != 4 && t.size() != 5) throw std::invalid_argument("not a pickled plantsim.World");
  PyWorld w = load(t[0], t[1], t[2], "", py::int_(0));
  if (worlds::world_fingerprint(*w.world) != t[3].cast<std::uint64_t>())
    throw std::invalid_argument(w.world->source + ": the file no longer holds the pickled world");
  if (t.size() == 5) w = renamed(w, t[4].cast<std::string>());
  return w;
}

}  // namespace

PyWorld world_argument(const py::handle& value) {
  if (py::isinstance<PyWorld>(value)) return value.cast<PyWorld>();
  if (py::isinstance<py::str>(value) || py::hasattr(value, "__fspath__"))
    return load(py::reinterpret_borrow<py::object>(value), py::none(), py::none(), "", py::int_(0));
  throw py::type_error("world must be a plantsim.World or the path of a world file, got " +
                       py::str(py::type::of(value).attr("__name__")).cast<std::string>());
}

void bind_world(py::module_& m) {
  py::class_<PyWorld>(
      m, "World", "A plant: floor, rectangles, start and charger poses, robot (SI units, y up).")
      .def_property(
          "name", [](const PyWorld& w) { return w.world->name; },
          [](PyWorld& w, const std::string& name) { w = renamed(w, name); },
          "the name records, episode ids and figures use (settable; kept when pickled)")
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
      .def(py::pickle(&world_state, &world_from_state));
  m.def(
      "load_world", &load, py::arg("path"), py::kw_only(), py::arg("start") = py::none(),
      py::arg("charger") = py::none(), py::arg("scen") = "", py::arg("query") = 0,
      R"(Loads a world: plantsim JSON, a plain benchmark world, a ROS map_server YAML or a MovingAI .map.

start, charger: (x, y, yaw) overriding the file's poses. scen, query: for a MovingAI map, the
.scen file and the query number that give the start and the charger. Raises plantsim.InputError
naming the file and the field, as `plantsim run` does.)");
}

}  // namespace plantsim::python
