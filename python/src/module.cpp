// SPDX-License-Identifier: BSD-3-Clause
/// The `edgetrack` Python module (edgetrack._edgetrack, re-exported by the package): its
/// exception and its parts.
#include "bindings.h"

namespace edgetrack_python {

namespace {
PyObject* error_type = nullptr;  ///< edgetrack.Error, made once when the module loads
}  // namespace

void raise(const std::string& message) {
  PyErr_SetString(error_type, message.c_str());
  throw py::error_already_set();
}

void raise(const edgetrack::Error& error) { raise(error.text()); }

}  // namespace edgetrack_python

PYBIND11_MODULE(_edgetrack, m) {
  namespace py = pybind11;
  m.doc() = "edgetrack: markerless edge-based 3D tracking of a wireframe model (docs/PYTHON.md).";
  static py::exception<edgetrack::Error> error(m, "Error", PyExc_ValueError);
  error.doc() = "A refused input or call, with the command line's one-line message (file:line: message).";
  edgetrack_python::error_type = error.ptr();
  m.attr("real") = real_name();
  edgetrack_python::bind_inputs(m);
  edgetrack_python::bind_results(m);
  edgetrack_python::bind_tracking(m);
}
