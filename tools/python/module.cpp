// The Python module `metalfit` (docs/python.md): catalog(), reference(), fit(), evaluate(), export() over libfit,
// through the CLI's own option structs (calls.hpp), so that records equal `metalfit fit --json`'s and errors carry
// the CLI's one-line messages. Only argument conversion, the GIL and the exceptions live here.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <exception>
#include <optional>
#include <string>
#include <vector>

#include "calls.hpp"
#include "libfit/base/errors.hpp"
#include "libfit/base/library_logging.hpp"
#include "libfit/base/version.hpp"
#include "libfit/models/model.hpp"
#include "module_data_dir.hpp"

namespace py = pybind11;

namespace metalfit::python {
namespace {

using Array = py::array_t<double, py::array::c_style | py::array::forcecast>;

// The exception types (metalfit.Error and its subclasses), created once at import; the module holds them.
struct ExceptionTypes {
    PyObject* error = nullptr;
    PyObject* usage = nullptr;
    PyObject* input = nullptr;
    PyObject* colour = nullptr;
};
ExceptionTypes g_types;

PyObject* add_exception(py::module_& m, const char* name, const char* doc, py::handle bases, int exit_code) {
    const std::string qualified = std::string("metalfit.") + name;
    PyObject* type = PyErr_NewExceptionWithDoc(qualified.c_str(), doc, bases.ptr(), nullptr);
    if (!type) throw py::error_already_set();
    py::handle(type).attr("exit_code") = exit_code;
    m.attr(name) = py::handle(type);  // the module keeps a reference for as long as the process lives
    return type;
}

// str, os.PathLike, or a list of them → the CLI's positional material arguments.
std::vector<std::string> material_arguments(const py::object& material) {
    std::vector<std::string> arguments;
    if (material.is_none()) return arguments;
    const py::module_ os = py::module_::import("os");
    if (py::isinstance<py::list>(material) || py::isinstance<py::tuple>(material)) {
        for (const py::handle item : material) arguments.push_back(py::str(os.attr("fspath")(item)));
    } else {
        arguments.push_back(py::str(os.attr("fspath")(material)));
    }
    return arguments;
}

// A list of ids or one comma-separated string → the CLI's "m1,m2".
std::string comma_list(const py::object& value) {
    if (py::isinstance<py::str>(value)) return value.cast<std::string>();
    std::string list;
    for (const py::handle item : value) list += (list.empty() ? "" : ",") + py::str(item).cast<std::string>();
    return list;
}

cli::GlobalOptions global_options(const std::optional<std::string>& data_dir,
                                  const std::optional<std::string>& ocio_config) {
    cli::GlobalOptions global{data_dir ? std::filesystem::path(*data_dir) : module_data_dir(), std::nullopt};
    if (ocio_config) global.ocio_config = *ocio_config;
    return global;
}

cli::ColourOptions colour_options(const std::optional<std::string>& space, const std::string& convention,
                                  const std::optional<std::string>& cmf, const std::optional<std::string>& illuminant,
                                  const std::optional<std::string>& adaptation, const std::string& interp,
                                  bool extrapolate, const std::optional<std::string>& xyz_space) {
    cli::ColourOptions o;
    o.space = space.value_or("");
    o.xyz_space = xyz_space.value_or("");
    o.convention = convention;
    o.cmf = cmf;
    o.illuminant = illuminant;
    o.adaptation = adaptation;
    o.interpolation = interp;
    o.extrapolate = extrapolate;
    return o;
}

cli::MaterialSelection selection(const py::object& material, bool all, const std::optional<std::string>& source,
                                 const std::optional<std::string>& name, const std::optional<std::string>& reference) {
    cli::MaterialSelection s;
    s.arguments = material_arguments(material);
    s.all = all;
    s.source = source.value_or("");
    s.labels.name = name.value_or("");
    s.labels.reference = reference.value_or("");
    return s;
}

cli::LayerOptions layers(const std::optional<std::string>& film, const std::optional<std::string>& coat) {
    return {film.value_or(""), coat.value_or("")};
}

py::object json_loads(const std::string& text) { return py::module_::import("json").attr("loads")(text); }

// The CLI's own checks that CLI11 makes before libfit sees a value.
void check_nodes(int nodes) {
    if (nodes < 2 || nodes > 4096)
        throw UsageError("--nodes: Value " + std::to_string(nodes) + " not in range 2 to 4096");
}

py::object catalog(const std::optional<std::string>& data_dir) {
    const cli::GlobalOptions global = global_options(data_dir, std::nullopt);
    std::string text;
    {
        py::gil_scoped_release release;
        text = catalog_json(global);
    }
    return json_loads(text);
}

py::array reference_curve(const py::object& material, const py::object& mu_object,
                          const std::optional<std::string>& space, const std::string& convention,
                          const std::optional<std::string>& cmf, const std::optional<std::string>& illuminant,
                          const std::optional<std::string>& adaptation, const std::string& interp, bool extrapolate,
                          const std::optional<std::string>& xyz_space, const std::optional<std::string>& source,
                          const std::optional<std::string>& film, const std::optional<std::string>& coat,
                          const std::optional<std::string>& data_dir, const std::optional<std::string>& ocio_config) {
    const py::module_ np = py::module_::import("numpy");
    const Array mu = Array::ensure(mu_object.is_none() ? np.attr("linspace")(0.0, 1.0, 101) : mu_object);
    if (!mu) throw py::error_already_set();
    ReferenceOptions options{
        selection(material, false, source, std::nullopt, std::nullopt), layers(film, coat),
        colour_options(space, convention, cmf, illuminant, adaptation, interp, extrapolate, xyz_space)};
    const cli::GlobalOptions global = global_options(data_dir, ocio_config);
    std::vector<py::ssize_t> shape(mu.shape(), mu.shape() + mu.ndim());
    shape.push_back(3);
    Array out(shape);
    {
        const std::span<const double> values(mu.data(), static_cast<std::size_t>(mu.size()));
        double* target = out.mutable_data();
        py::gil_scoped_release release;
        const std::vector<RGB> curve = reference(options, global, values);
        for (std::size_t i = 0; i < curve.size(); ++i)
            for (int c = 0; c < 3; ++c) target[3 * i + c] = curve[i][c];
    }
    return out;
}

py::object fit(const py::object& material, bool all, const py::object& models, const std::optional<std::string>& space,
               const std::string& convention, const std::optional<std::string>& cmf,
               const std::optional<std::string>& illuminant, const std::optional<std::string>& adaptation,
               const std::string& interp, bool extrapolate, const std::optional<std::string>& xyz_space,
               const std::string& metric, const std::string& weight, int nodes, const std::optional<std::string>& pin,
               bool gamut_fit, const std::optional<std::string>& budget, const std::string& budget_metric,
               const std::optional<std::string>& costs, const std::optional<std::string>& source,
               const std::optional<std::string>& name, const std::optional<std::string>& reference_text,
               const std::optional<std::string>& film, const std::optional<std::string>& coat, int jobs,
               const std::optional<std::string>& data_dir, const std::optional<std::string>& ocio_config) {
    check_nodes(nodes);
    if (jobs < 0) throw UsageError("--jobs: Value " + std::to_string(jobs) + " should be greater than or equal to 0");
    FitOptions o;
    o.selection = selection(material, all, source, name, reference_text);
    o.layers = layers(film, coat);
    o.models = comma_list(models);
    o.colour = colour_options(space, convention, cmf, illuminant, adaptation, interp, extrapolate, xyz_space);
    o.error = {metric, weight, nodes};
    o.jobs = jobs;
    o.pin = pin.value_or("");
    o.gamut_fit = gamut_fit;
    o.budget = budget.value_or("");
    o.budget_metric = budget_metric;
    if (costs) o.costs = *costs;
    const cli::GlobalOptions global = global_options(data_dir, ocio_config);
    std::string text;
    {
        py::gil_scoped_release release;  // the fit runs on libfit's threads while Python goes on
        text = fit_json(o, global);
    }
    return json_loads(text);
}

std::vector<std::string>
export_(const py::object& material, const py::object& output, const py::object& models, const py::object& formats,
        bool all, const std::string& params, const std::string& gamut, bool gamut_fit, const py::object& roughness,
        const std::optional<std::string>& id_prefix, const std::optional<std::string>& space,
        const std::string& convention, const std::optional<std::string>& cmf,
        const std::optional<std::string>& illuminant, const std::optional<std::string>& adaptation,
        const std::string& interp, bool extrapolate, const std::optional<std::string>& xyz_space,
        const std::optional<std::string>& source, const std::optional<std::string>& name,
        const std::optional<std::string>& reference_text, const std::optional<std::string>& film,
        const std::optional<std::string>& coat, int jobs, const std::optional<std::string>& data_dir,
        const std::optional<std::string>& ocio_config) {
    if (jobs < 0) throw UsageError("--jobs: Value " + std::to_string(jobs) + " should be greater than or equal to 0");
    ExportOptions o;
    o.selection = selection(material, all, source, name, reference_text);
    o.layers = layers(film, coat);
    o.models = comma_list(models);
    o.formats = comma_list(formats);
    o.params = params;
    o.gamut = gamut;
    o.gamut_fit = gamut_fit;
    o.roughness = roughness.is_none() ? std::string() : py::str(roughness).cast<std::string>();
    o.id_prefix = id_prefix.value_or("");
    o.colour = colour_options(space, convention, cmf, illuminant, adaptation, interp, extrapolate, xyz_space);
    o.jobs = jobs;
    o.output = py::str(py::module_::import("os").attr("fspath")(output)).cast<std::string>();
    const cli::GlobalOptions global = global_options(data_dir, ocio_config);
    py::gil_scoped_release release;
    return export_folder(o, global);
}

// The model's parameters as an array of shape (..., P, 3): from an array of that shape, or from a mapping of the
// parameter names (a fit record's "params") to arrays of shape (..., 3), broadcast against each other.
Array parameter_array(const Model& model, const py::object& params) {
    const auto parameters = model.parameters();
    const py::module_ np = py::module_::import("numpy");
    std::string names;
    for (const Parameter& p : parameters) names += (names.empty() ? "" : ", ") + std::string(p.name);
    const std::string expected = std::string(model.id()) + "'s parameters: " + names;
    py::object stacked = params;
    if (py::isinstance<py::dict>(params)) {
        const py::dict d = params.cast<py::dict>();
        py::list arrays;
        for (const Parameter& p : parameters) {
            const py::str key(std::string(p.name));
            if (!d.contains(key))
                throw py::value_error("evaluate: params lacks '" + std::string(p.name) + "' (" + expected + ")");
            arrays.append(np.attr("asarray")(d[key], "float64"));
        }
        for (const auto& [key, value] : d)
            if (std::none_of(parameters.begin(), parameters.end(), [&](const Parameter& p) {
                    return std::string(p.name) == py::str(key).cast<std::string>();
                }))
                throw py::value_error("evaluate: unknown parameter '" + py::str(key).cast<std::string>() + "' (" +
                                      expected + ")");
        stacked = np.attr("stack")(np.attr("broadcast_arrays")(*arrays), -2);
    }
    Array array = Array::ensure(stacked);
    if (!array) throw py::error_already_set();
    const auto count = static_cast<py::ssize_t>(parameters.size());
    if (array.ndim() < 2 || array.shape(array.ndim() - 2) != count || array.shape(array.ndim() - 1) != 3)
        throw py::value_error("evaluate: params must have shape (..., " + std::to_string(count) +
                              ", 3): one R, G, B triple per parameter (" + expected + ")");
    return array;
}

py::array evaluate(const std::string& model_id, const py::object& params, const py::object& mu_object) {
    const Model& model = find_model(model_id);
    const py::module_ np = py::module_::import("numpy");
    const Array p = parameter_array(model, params);
    const Array mu = Array::ensure(mu_object);
    if (!mu) throw py::error_already_set();
    const py::tuple p_shape = py::tuple(p.attr("shape"));
    const py::tuple batch_of_p = p_shape[py::slice(0, p.ndim() - 2, 1)];
    const py::tuple batch = np.attr("broadcast_shapes")(mu.attr("shape"), batch_of_p);
    const py::tuple params_shape = batch + py::make_tuple(p_shape[p.ndim() - 2], 3);
    const Array mu_b = Array::ensure(np.attr("ascontiguousarray")(np.attr("broadcast_to")(mu, batch)));
    const Array p_b = Array::ensure(np.attr("ascontiguousarray")(np.attr("broadcast_to")(p, params_shape)));
    std::vector<py::ssize_t> shape;
    for (const py::handle d : batch) shape.push_back(d.cast<py::ssize_t>());
    shape.push_back(3);
    Array out(shape);
    const std::size_t count = model.parameters().size();
    const double* mus = mu_b.data();
    const double* values = p_b.data();
    double* target = out.mutable_data();
    const auto n = static_cast<std::size_t>(mu_b.size());
    {
        py::gil_scoped_release release;
        std::vector<double> channel(count);
        for (std::size_t i = 0; i < n; ++i)
            for (std::size_t c = 0; c < 3; ++c) {
                for (std::size_t k = 0; k < count; ++k) channel[k] = values[(i * count + k) * 3 + c];
                target[3 * i + c] = model.evaluate(std::span<const double>(channel), mus[i]);
            }
    }
    return out;
}

py::list models() {
    py::list list;
    for (const Model* m : all_models()) {
        py::list names;
        for (const Parameter& p : m->parameters()) names.append(std::string(p.name));
        py::dict entry;
        entry["id"] = std::string(m->id());
        entry["title"] = std::string(m->title());
        entry["parameters"] = names;
        list.append(entry);
    }
    return list;
}

}  // namespace
}  // namespace metalfit::python

PYBIND11_MODULE(metalfit, m) {
    using namespace metalfit;
    using namespace metalfit::python;
    using py::arg;
    route_library_logging("metalfit");
    m.doc() = "metalfit: fit shader Fresnel models to measured metal n,k (docs/python.md)";
    m.attr("__version__") = METALFIT_VERSION;

    g_types.error = add_exception(m, "Error", "A metalfit error; str(e) is the CLI's one-line message.",
                                  PyExc_Exception, exit_internal);
    g_types.usage = add_exception(m, "UsageError", "A request metalfit cannot understand (CLI exit code 2).",
                                  py::make_tuple(py::handle(g_types.error), py::handle(PyExc_ValueError)), exit_usage);
    g_types.input = add_exception(m, "InputError", "A bad input file or bad data in it (CLI exit code 3).",
                                  g_types.error, exit_bad_input);
    g_types.colour = add_exception(m, "ColourConfigError", "An OCIO configuration problem (CLI exit code 4).",
                                   g_types.error, exit_colour_config);
    py::register_exception_translator([](std::exception_ptr error) {
        // The messages report_current_exception prints after "metalfit: " (libfit/src/base/errors.cpp).
        try {
            if (error) std::rethrow_exception(error);
        } catch (const UsageError& e) {
            PyErr_SetString(g_types.usage, sanitised_message(e.what()).c_str());
        } catch (const InputError& e) {
            PyErr_SetString(g_types.input, e.what());
        } catch (const ColorConfigError& e) {
            PyErr_SetString(g_types.colour, sanitised_message(e.what()).c_str());
        }
    });

    m.def(
        "data_dir", [] { return module_data_dir().string(); },
        "The database the functions use by default: $METALFIT_DATA, else the one installed with the module, else "
        "the source tree's data/.");
    m.def("catalog", &catalog, py::kw_only(), arg("data_dir") = py::none(),
          "The catalog's materials: the list `metalfit list --json` prints, as dicts.");
    m.def("models", &models, "The models: id, title and parameter names, in the registry's order.");
    m.def("reference", &reference_curve, arg("material"), arg("mu") = py::none(), py::kw_only(),
          arg("space") = py::none(), arg("convention") = "metalfit", arg("cmf") = py::none(),
          arg("illuminant") = py::none(), arg("adaptation") = py::none(), arg("interp") = "linear",
          arg("extrapolate") = false, arg("xyz_space") = py::none(), arg("source") = py::none(),
          arg("film") = py::none(), arg("coat") = py::none(), arg("data_dir") = py::none(),
          arg("ocio_config") = py::none(),
          "R_c(mu) of one material (catalog name or file) as `metalfit show` computes it: an array of shape "
          "mu.shape + (3,) (default mu: 101 values from 0 to 1).");
    m.def("fit", &fit, arg("material") = py::none(), py::kw_only(), arg("all") = false, arg("models") = "all",
          arg("space") = py::none(), arg("convention") = "metalfit", arg("cmf") = py::none(),
          arg("illuminant") = py::none(), arg("adaptation") = py::none(), arg("interp") = "linear",
          arg("extrapolate") = false, arg("xyz_space") = py::none(), arg("metric") = "rel", arg("weight") = "uniform",
          arg("nodes") = 128, arg("pin") = py::none(), arg("gamut_fit") = false, arg("budget") = py::none(),
          arg("budget_metric") = "rel_rms", arg("costs") = py::none(), arg("source") = py::none(),
          arg("name") = py::none(), arg("reference") = py::none(), arg("film") = py::none(), arg("coat") = py::none(),
          arg("jobs") = 0, arg("data_dir") = py::none(), arg("ocio_config") = py::none(),
          "Fits the models to the materials: the record `metalfit fit --json` prints, as a dict. The GIL is "
          "released while fitting.");
    m.def("evaluate", &evaluate, arg("model"), arg("params"), arg("mu"),
          "The model at mu with params (shape (..., P, 3), or a dict of the parameter names to (..., 3)), "
          "broadcast: an array of shape broadcast(mu.shape, params.shape[:-2]) + (3,).");
    m.def("export", &export_, arg("material") = py::none(), py::kw_only(), arg("output"), arg("models"), arg("formats"),
          arg("all") = false, arg("params") = "fit", arg("gamut") = "keep", arg("gamut_fit") = false,
          arg("roughness") = py::none(), arg("id_prefix") = py::none(), arg("space") = py::none(),
          arg("convention") = "metalfit", arg("cmf") = py::none(), arg("illuminant") = py::none(),
          arg("adaptation") = py::none(), arg("interp") = "linear", arg("extrapolate") = false,
          arg("xyz_space") = py::none(), arg("source") = py::none(), arg("name") = py::none(),
          arg("reference") = py::none(), arg("film") = py::none(), arg("coat") = py::none(), arg("jobs") = 0,
          arg("data_dir") = py::none(), arg("ocio_config") = py::none(),
          "Writes an export folder as `metalfit export` does; returns the files written, relative to it.");
}
