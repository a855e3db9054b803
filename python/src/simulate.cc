// hecal.simulate (docs/python.md#simulation): `hecal simulate`, the thesis study over sweeps
// (jobs::Simulate, docs/thesis-study.md), from the CLI's flags as keywords. Returns a dict:
// summary (one dict per setting and method: the columns of `--summary` with numbers as floats),
// summary_csv and trials_csv (the bytes `hecal simulate --summary / --output` write), seed. The
// GIL is released while the study runs (on `threads` workers; 0 = every core).
#include <charconv>
#include <optional>
#include <utility>
#include <sstream>
#include <string>

#include "bindings.h"

namespace hecal::python {
namespace {

std::vector<std::string> SplitCsvLine(const std::string& line) {
  std::vector<std::string> fields;
  std::string field;
  bool quoted = false;
  for (char c : line) {
    if (c == '"') {
      quoted = !quoted;
    } else if (c == ',' && !quoted) {
      fields.push_back(field);
      field.clear();
    } else {
      field += c;
    }
  }
  fields.push_back(field);
  return fields;
}

py::list CsvRows(const std::string& text) {
  py::list rows;
  std::istringstream in(text);
  std::string line;
  std::vector<std::string> header;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    const std::vector<std::string> fields = SplitCsvLine(line);
    if (header.empty()) {
      header = fields;
      continue;
    }
    py::dict row;
    for (size_t k = 0; k < header.size() && k < fields.size(); ++k) {
      const std::string& f = fields[k];
      double value = 0.0;
      const auto [end, error] = std::from_chars(f.data(), f.data() + f.size(), value);
      if (!f.empty() && error == std::errc() && end == f.data() + f.size()) {
        row[py::str(header[k])] = value;
      } else {
        row[py::str(header[k])] = f;
      }
    }
    rows.append(row);
  }
  return rows;
}

template <typename T, typename Parse>
std::vector<T> Choices(const std::string& argument, const std::vector<std::string>& names,
                       Parse parse, const std::string& allowed) {
  std::vector<T> out;
  for (const std::string& name : names) {
    const auto value = parse(name);
    if (!value) ThrowArgument(argument, "unknown value '" + name + "'", "use " + allowed);
    out.push_back(*value);
  }
  return out;
}

constexpr const char* kSimulateDoc = R"doc(simulate(stations=[3, 5, 10, 15, 20], sigmas=[0, 0.3, 1], setups=["eye-in-hand"], methods="all", trials=200, ...) -> dict

The thesis study (`hecal simulate`, docs/thesis-study.md): every method on simulated data
over the Cartesian product of the sweeps; each list sweeps.

stations      stations per data set (3 to 100000)
sigmas        noise levels: n (= n mm and n deg per component) or (mm, deg)
setups        "eye-in-hand" | "eye-to-hand"
noise_on      "robot" | "camera" | "both";  noise: "gaussian" | "uniform" | "systematic" |
              "student-t3" | "pnp"
outliers      gross outliers per data set;  robot_scales: robot noise = scale x level
methods       method names, or "all"
trials        data sets per setting;  seed;  threads (0 = every core)
covariance    None (no covariance), "default" (each method's own), "linear", "unscented",
              "montecarlo": X's predicted covariance and its consistency
reject_outliers, estimate_noise   as the CLI's --reject-outliers, --estimate-noise

Returns {"summary": [one dict per setting and method: the --summary columns, numbers as
floats], "summary_csv": str, "trials_csv": str (the --summary / --output files), "seed": int}.)doc";

}  // namespace

void RegisterSimulate(py::module_& m) {
  m.def(
      "simulate",
      [](std::vector<int> stations, py::handle sigmas, std::vector<std::string> setups,
         std::vector<std::string> noise_on, std::vector<std::string> noise,
         std::vector<int> outliers, std::vector<double> robot_scales, py::handle methods,
         int trials, std::uint64_t seed, int threads, std::optional<std::string> covariance,
         int covariance_samples, bool reject_outliers, bool estimate_noise) {
        jobs::SimulateOptions o;
        o.stations = std::move(stations);
        o.sigmas.clear();
        for (py::handle level : py::reinterpret_borrow<py::sequence>(sigmas)) {
          if (py::isinstance<py::sequence>(level) && !py::isinstance<py::str>(level)) {
            const auto pair = level.cast<std::pair<double, double>>();
            o.sigmas.push_back({pair.first, pair.second});
          } else {
            const double n = level.cast<double>();
            o.sigmas.push_back({n, n});
          }
        }
        o.setups = Choices<handeye::Setup>("setups", setups, handeye::ParseSetup,
                                           "eye-in-hand or eye-to-hand");
        o.noise_on = Choices<study::NoiseOn>("noise_on", noise_on, study::ParseNoiseOn,
                                             "robot, camera or both");
        o.noise = Choices<sim::NoiseModel::Kind>(
            "noise", noise, sim::ParseNoiseKind,
            "gaussian, uniform, systematic, student-t3 or pnp");
        o.outliers = std::move(outliers);
        o.robot_scales = std::move(robot_scales);
        if (py::isinstance<py::str>(methods)) {
          const std::string name = methods.cast<std::string>();
          if (name == "all") {
            o.methods = study::EveryMethod();
          } else {
            o.methods = Choices<estimation::Method>("methods", {name}, estimation::ParseMethod,
                                                    "method names or \"all\"");
          }
        } else {
          o.methods = Choices<estimation::Method>("methods",
                                                  methods.cast<std::vector<std::string>>(),
                                                  estimation::ParseMethod, "method names");
        }
        o.trials = trials;
        o.seed = seed;
        o.threads = threads;
        if (!covariance) {
          o.covariance = estimation::CovarianceMethod::kNone;
        } else if (*covariance == "default") {
          o.covariance = std::nullopt;
        } else {
          const auto parsed = estimation::ParseCovarianceMethod(*covariance);
          if (!parsed) {
            ThrowArgument("covariance", "unknown covariance method '" + *covariance + "'",
                          "use None, \"default\", \"linear\", \"unscented\" or \"montecarlo\"");
          }
          o.covariance = parsed;
        }
        o.covariance_samples = covariance_samples;
        o.reject_outliers = reject_outliers;
        o.estimate_noise = estimate_noise;
        std::string summary, trials_csv;
        {
          py::gil_scoped_release release;
          const study::StudyResult result = jobs::Simulate(o);
          summary = study::SummaryCsv(result);
          trials_csv = study::TrialsCsv(result);
        }
        py::dict out;
        out["summary"] = CsvRows(summary);
        out["summary_csv"] = summary;
        out["trials_csv"] = trials_csv;
        out["seed"] = py::int_(seed);
        return out;
      },
      py::kw_only(), py::arg("stations") = std::vector<int>{3, 5, 10, 15, 20},
      py::arg("sigmas") = py::make_tuple(0.0, 0.3, 1.0),
      py::arg("setups") = std::vector<std::string>{"eye-in-hand"},
      py::arg("noise_on") = std::vector<std::string>{"both"},
      py::arg("noise") = std::vector<std::string>{"gaussian"},
      py::arg("outliers") = std::vector<int>{0}, py::arg("robot_scales") = std::vector<double>{1.0},
      py::arg("methods") = "all", py::arg("trials") = 200, py::arg("seed") = 1,
      py::arg("threads") = 0, py::arg("covariance") = py::none(),
      py::arg("covariance_samples") = 1000, py::arg("reject_outliers") = false,
      py::arg("estimate_noise") = false, kSimulateDoc);
}

}  // namespace hecal::python
