// The extension module impact3d._impact3d; the package impact3d (python/impact3d/) is its public face.
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "case.hpp"
#include "impact3d/studies/montecarlo.hpp"
#include "impact3d/studies/precision.hpp"
#include "impact3d/mechanics/lean.hpp"
#include "impact3d/scalar/thread_caches.hpp"
#include "solve.hpp"
#include "solve_batch.hpp"
#include "reconstruct.hpp"
#include "uncertainty.hpp"

namespace py = pybind11;
using namespace impact3d;
using namespace impact3d::python;

PYBIND11_MODULE(_impact3d, m) {
  m.doc() = "impact3d's C++ library; use the package impact3d";
  // Its functions release the GIL, so Python threads may solve at 50 or 100 digits at once.
  impact3d::fill_shared_before_threads();
  py::register_exception<InputError>(m, "CaseError", PyExc_ValueError);

  py::class_<Case>(m, "Case")
      .def_property_readonly("name", [](const Case& c) { return c.spec.name; })
      .def_property_readonly("source", [](const Case& c) { return c.source; })
      .def_property_readonly("text", [](const Case& c) { return c.text; })
      .def("__repr__", [](const Case& c) {
        return "<impact3d.Case " + py::repr(py::str(c.spec.name)).cast<std::string>() +
               (c.source.empty() ? std::string() : " from " + c.source) + ">";
      });
  m.def("read_case_file", &read_case_file, py::arg("path"), py::call_guard<py::gil_scoped_release>());
  m.def("read_case_text", &read_case_text, py::arg("text"), py::arg("source") = "",
        py::call_guard<py::gil_scoped_release>());

  m.def("solve_json", &solve_json, py::arg("case"), py::arg("strategies"), py::arg("engine"), py::arg("precision"),
        py::arg("units"), py::call_guard<py::gil_scoped_release>());
  add_solve_batch(m);

  py::class_<Uncertainty>(m, "Uncertainty")
      .def(py::init<std::string, std::string>(), py::arg("text"), py::arg("source") = "")
      .def_property_readonly("source", [](const Uncertainty& u) { return u.source; });
  m.def(
      "read_uncertainty_file",
      [](const std::string& path) { return Uncertainty{guarded(path, [&] { return case_format::read_text_file(path); }), path}; },
      py::arg("path"), py::call_guard<py::gil_scoped_release>());
  m.def("montecarlo", &montecarlo, py::arg("case"), py::arg("uncertainty"), py::arg("strategies"), py::arg("precision"),
        py::arg("engine"), py::arg("jobs"), py::arg("samples"), py::arg("seed"), py::arg("keep_samples"));
  m.def("sensitivity_json", &sensitivity_json, py::arg("case"), py::arg("strategies"), py::arg("engine"),
        py::call_guard<py::gil_scoped_release>());
  m.def(
      "read_input_file", [](const std::string& path) { return guarded(path, [&] { return case_format::read_text_file(path); }); },
      py::arg("path"), py::call_guard<py::gil_scoped_release>());
  m.def("reconstruct_json", &reconstruct_json, py::arg("case"), py::arg("evidence_text"), py::arg("evidence_source"),
        py::arg("strategy"), py::arg("engine"), py::call_guard<py::gil_scoped_release>());

  py::list precisions;
  for (const auto& p : studies::precision_names()) precisions.append(p);
  m.attr("PRECISIONS") = py::tuple(precisions);
  py::list regimes, warnings;
  for (const auto r : studies::kRegimeNames) regimes.append(std::string(r));
  for (const auto w : studies::kWarningNames) warnings.append(std::string(w));
  m.attr("REGIMES") = py::tuple(regimes);
  m.attr("WARNINGS") = py::tuple(warnings);
  m.attr("MAX_SAMPLES") = case_format::kMaxSamples;  // the bounds the package checks its arguments by
  m.attr("MAX_JOBS") = kMaxJobs;
  m.attr("STATUSES") = py::make_tuple(status_name(Status::solved), status_name(Status::not_approaching),
                                      status_name(Status::singular), "invalid");
}
