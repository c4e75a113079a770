/// The extension module symcontact._symcontact: Problem, run() and the exceptions. The package
/// python/symcontact/ re-exports them and wraps run()'s raw dict (study_run.hpp) in a Result; the
/// reference is docs/python.md.
///
/// Exceptions, with the command line's exit codes (docs/input.md) as their `exit_code`:
///   SymcontactError (base) ← InputError (2: file, key, message), SolveError (3), InternalError (4).

#include <cmath>
#include <cstdlib>

#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "problem.hpp"
#include "study_run.hpp"
#include "symcontact/core/blas_kernels.hpp"
#include "symcontact/core/blas_threads.hpp"
#include "symcontact/core/error.hpp"

namespace py = pybind11;
using namespace symcontact;
using symcontact::python::Problem;
using symcontact::python::StudyOptions;

namespace {

py::object new_exception(py::module_& m, const char* name, py::handle base, int exit_code, const char* doc) {
  py::object type = py::reinterpret_steal<py::object>(
      PyErr_NewExceptionWithDoc((std::string("symcontact.") + name).c_str(), doc, base.ptr(), nullptr));
  if (!type) throw py::error_already_set();
  type.attr("exit_code") = exit_code;
  m.attr(name) = type;
  return type;
}

/// Raises an instance of `type` with message `what` and the attributes `attrs`.
void raise(py::handle type, const std::string& what, const py::dict& attrs) {
  py::object exc = type(what);
  for (auto item : attrs) exc.attr(item.first) = item.second;
  PyErr_SetObject(type.ptr(), exc.ptr());
}

Verbosity verbosity_of(const std::string& name) {
  if (name == "quiet") return Verbosity::kQuiet;
  if (name == "normal") return Verbosity::kNormal;
  if (name == "verbose") return Verbosity::kVerbose;
  if (name == "debug") return Verbosity::kDebug;
  throw py::value_error("verbosity: expected \"quiet\", \"normal\", \"verbose\" or \"debug\", got \"" + name + "\"");
}

}  // namespace

PYBIND11_MODULE(_symcontact, m) {
  m.doc() = "symcontact: frictional contact by interior point (the compiled part; import symcontact)";
  m.attr("__version__") = SYMCONTACT_VERSION;
  // The types live as long as the module's attributes; the handles below (used by the translator) hold no
  // reference of their own, so that nothing is released after the interpreter has finalised.
  py::object base = new_exception(m, "SymcontactError", PyExc_Exception, kExitInternalError,
                                  "An error of symcontact; `exit_code` is the command line's exit code for it.");
  static py::handle input_error =
      new_exception(m, "InputError", base, kExitInputError,
                    "Bad input (exit code 2): `file`, `key` and `message` as in the command line's "
                    "'FILE: KEY: message'.")
          .release();
  static py::handle solve_error =
      new_exception(m, "SolveError", base, kExitSolveError, "A solve that failed (exit code 3).").release();
  static py::handle internal_error =
      new_exception(m, "InternalError", base, kExitInternalError, "An error of symcontact itself (exit code 4).")
          .release();

  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const InputError& e) {
      raise(input_error, e.what(), py::dict(py::arg("file") = e.file(), py::arg("key") = e.key(),
                                            py::arg("message") = e.message()));
    } catch (const SolveError& e) {
      raise(solve_error, e.what(), py::dict(py::arg("result") = py::none()));
    } catch (const py::builtin_exception&) {
      throw;  // KeyError, IndexError, TypeError, ...: pybind11's own translation
    } catch (const std::bad_alloc&) {
      throw;  // MemoryError
    } catch (const std::exception& e) {
      raise(internal_error, e.what(), py::dict());
    }
  });

  py::class_<Problem>(m, "Problem", "A problem file as an editable TOML document, validated at every change.")
      .def_static("from_file", &Problem::from_file, py::arg("path"))
      .def_static("from_string", &Problem::from_string, py::arg("text"), py::arg("base_dir") = "",
                  py::arg("name") = "<string>")
      .def("get", &Problem::get, py::arg("key"))
      .def("set", &Problem::set, py::arg("key"), py::arg("value"))
      .def("remove", &Problem::remove, py::arg("key"))
      .def("update", &Problem::update, py::arg("changes"))
      .def("__contains__", &Problem::contains)
      .def("to_dict", &Problem::as_dict)
      .def_property_readonly("toml", &Problem::toml_text)
      .def_property_readonly("name", &Problem::name)
      .def_property_readonly("base_dir", &Problem::base_dir)
      .def_property_readonly("dimension", [](const Problem& p) { return p.spec().dim; })
      .def_property_readonly("num_steps", [](const Problem& p) { return p.spec().load_factors.size(); });

  m.def(
      "blas_kernels",
      [] {
        const std::string core = blas_core_name();
        py::dict d;
        d["core"] = core;
        d["better"] = better_blas_core(core);
        return d;
      },
      "The OpenBLAS kernel family this process runs ('' when the BLAS is not OpenBLAS) and, where OpenBLAS fell "
      "back to one without AVX on a CPU with AVX2, the family `symcontact` would restart with ('' otherwise).");

  m.def(
      "run",
      [](const Problem& problem, const py::object& out_dir, const py::object& progress, double mesh_size,
         bool allow_large_mesh, bool allow_geo_commands, bool write_vtu, const std::string& verbosity, int threads) {
        // BLAS threads as the command line sets them (--threads; default 1 unless OPENBLAS_NUM_THREADS is
        // set): the same thread count gives the same sums, so the same digits as `symcontact run`.
        apply_thread_setting(threads);
        StudyOptions o;
        o.files = out_dir.is_none() ? OutputFiles::kNone : OutputFiles::kWrite;
        if (!out_dir.is_none()) o.out_dir = py::str(out_dir);
        o.progress = progress;
        if (mesh_size != 0.0 && !(std::isfinite(mesh_size) && mesh_size > 0.0))
          throw InputError("", "mesh_size", "expected a finite element size > 0 (or 0: the file's), got " +
                                                std::string(py::str(py::float_(mesh_size))));
        o.meshing.mesh_size = mesh_size;
        if (allow_large_mesh) o.meshing.max_predicted_cells = 0.0;
        o.meshing.geo_commands = allow_geo_commands ? GeoCommands::kAllow : GeoCommands::kRefuse;
        o.write_vtu = write_vtu;
        o.verbosity = verbosity_of(verbosity);
        return symcontact::python::run_study(problem, o);
      },
      py::arg("problem"), py::arg("out_dir") = py::none(), py::arg("progress") = py::none(),
      py::arg("mesh_size") = 0.0, py::arg("allow_large_mesh") = false, py::arg("allow_geo_commands") = false,
      py::arg("write_vtu") = true, py::arg("verbosity") = "quiet", py::arg("threads") = 0);
}
