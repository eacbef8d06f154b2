// The tuning's outputs, every number from the outcome's evaluations.
#include "tune/tune_report.h"

#include <cmath>
#include <nlohmann/json.hpp>
#include <sstream>

#include "render/palette.h"
#include "render/png_io.h"
#include "render/report.h"
#include "render/tune_charts.h"
#include "tune/part_runner.h"
#include "util/atomic_file.h"
#include "util/csv.h"
#include "util/fixed_text.h"

namespace plantsim::tune {

namespace {

using nlohmann::ordered_json;
using util::fixed;

std::string label(const std::string& name, const TuneSpec& spec) {
  if (name == "nlopt") return "NLopt " + method_name(spec.method);
  if (name == "random") return "random search";
  return "default settings";
}

std::string optional_text(const std::optional<double>& v, double scale, int decimals) {
  return v ? fixed(*v * scale, decimals) : "-";
}

ordered_json statistics_json(const Statistics& s) {
  ordered_json j;
  j["episodes"] = s.episodes;
  j["succeeded"] = s.succeeded;
  j["success_rate"] = s.success_rate;
  j["wilson_low"] = s.wilson_low;
  j["wilson_high"] = s.wilson_high;
  j["mean_time_s"] = s.mean_time_s ? ordered_json(*s.mean_time_s) : ordered_json(nullptr);
  j["mean_position_error_m"] =
      s.mean_position_error_m ? ordered_json(*s.mean_position_error_m) : ordered_json(nullptr);
  j["contacts"] = s.contacts;
  return j;
}

ordered_json values_json(const TuneSpec& spec, const std::vector<double>& values) {
  ordered_json j;
  for (std::size_t i = 0; i < spec.parameters.size(); ++i)
    j[spec.parameters[i].info.path] = values[i];
  return j;
}

ordered_json paired_json(const PairedComparison& c) {
  ordered_json j;
  j["pairs"] = c.pairs;
  j["docked_only_by_tuned"] = c.only_b;
  j["docked_only_by_default"] = c.only_a;
  j["mcnemar_p"] = c.success_p;
  j["both_docked"] = c.both_docked;
  j["mean_time_difference_s"] = c.time_difference_s;
  j["time_difference_95_low_s"] = c.time_low_s;
  j["time_difference_95_high_s"] = c.time_high_s;
  j["time_change"] = c.time_change;
  j["sign_test_p"] = c.time_p;
  return j;
}

const Proven& best_proven(const TuneOutcome& o) { return o.proven[o.best == "nlopt" ? 1 : 2]; }

/// The verdict in words: what the tuned settings did on the held-out episodes against the default.
std::string verdict_text(const TuneSpec& spec, const TuneOutcome& o) {
  const Proven& d = o.proven[0];
  const Proven& b = best_proven(o);
  const PairedComparison& c = o.best_against_default;
  std::ostringstream s;
  s << "On " << o.validation_episodes << " held-out validation episodes, the tuned settings ("
    << label(o.best, spec) << "'s best) docked " << b.validation.stats.succeeded
    << " (Wilson 95 % low " << fixed(b.validation.stats.wilson_low, 3) << ") against the default's "
    << d.validation.stats.succeeded << " (" << fixed(d.validation.stats.wilson_low, 3) << "); "
    << c.only_b << " episode(s) docked only tuned, " << c.only_a
    << " only default, McNemar exact p = " << fixed(c.success_p, 4) << ". ";
  if (c.both_docked > 0)
    s << "On the " << c.both_docked << " episodes both docked, the tuned settings' time to dock "
      << "differed from the default's by " << fixed(c.time_difference_s, 1)
      << " s on average (95 % "
      << "interval " << fixed(c.time_low_s, 1) << " to " << fixed(c.time_high_s, 1) << " s; "
      << fixed(100 * c.time_change, 1)
      << " % of the default's mean; sign test p = " << fixed(c.time_p, 4) << ").";
  return s.str();
}

ordered_json summary_json(const TuneSpec& spec, const TuneOutcome& o, const util::MadeBy& made_by) {
  ordered_json j;
  j["kind"] = "tune";
  j["name"] = spec.tuning.name;
  j["scenario"] = spec.scenario;
  j["objective"] = objective_name(spec.objective);
  j["objective_description"] = objective_description(spec.objective);
  j["method"] = method_name(spec.method);
  j["budget"] = spec.budget;
  j["seed"] = spec.seed;
  j["success_floor"] = o.floor;
  j["tuning_episodes"] = o.tuning_episodes;
  j["validation_episodes"] = o.validation_episodes;
  j["evaluations_run"] = o.evaluations_run;
  j["evaluations_reused"] = o.evaluations_reused;
  ordered_json params = ordered_json::array();
  for (const TunedParameter& p : spec.parameters)
    params.push_back(
        {{"key", p.info.path}, {"low", p.lo}, {"high", p.hi}, {"default", p.info.default_value}});
  j["parameters"] = params;
  ordered_json settings = ordered_json::array();
  for (const Proven& p : o.proven) {
    ordered_json s;
    s["setting"] = p.name;
    s["values"] = values_json(spec, p.tuning.values);
    s["tuning_score"] = p.tuning.score.value;  // the search's own measure, not a verdict
    s["tuning_evaluation"] = p.tuning.index + 1;
    s["tuning"] = statistics_json(p.tuning.stats);
    s["validation"] = statistics_json(p.validation.stats);
    settings.push_back(s);
  }
  j["settings"] = settings;
  j["best"] = o.best;
  j["tuned_against_default_on_validation"] = paired_json(o.best_against_default);
  j["verdict"] = verdict_text(spec, o);
  j["made_by"] = made_by.json();
  return j;
}

/// What the charts' score axis measures, in its units.
std::string score_label(Objective o) {
  switch (o) {
    case Objective::kTime:
      return "score: minus the mean time to dock (s)";
    case Objective::kDockingError:
      return "score: minus the mean docking error (m)";
    case Objective::kContacts:
      return "score: minus the contacts per episode";
    case Objective::kSuccess:
      return "score: Wilson 95 % low of the success rate";
    case Objective::kSuccessThenTime:
      break;
  }
  return "score: Wilson 95 % low minus 0.0001 per second of mean time to dock";
}

std::vector<render::SearchScores> search_scores(const TuneSpec& spec, const TuneOutcome& o) {
  std::vector<render::SearchScores> out = {
      {label("nlopt", spec), render::palette::kOkabeBlue, {}, {}, {}},
      {label("random", spec), render::palette::kOkabeOrange, {}, {}, {}}};
  for (const Evaluation& e : o.history) {
    if (e.search != "nlopt" && e.search != "random") continue;
    render::SearchScores& s = out[e.search == "nlopt" ? 0 : 1];
    s.score.push_back(e.score.value);
    s.counted.push_back(e.score.feasible && e.problem.empty());
    s.values.push_back(e.values);
  }
  return out;
}

void write_charts(const TuneSpec& spec, const TuneOutcome& o, const std::string& dir) {
  const std::vector<render::SearchScores> searches = search_scores(spec, o);
  const std::string y = score_label(spec.objective);
  render::write_png(
      render::draw_convergence_chart(searches, o.proven[0].tuning.score.value,
                                     "Tuning " + spec.tuning.name + ": " + label("nlopt", spec) +
                                         " against random search, " + std::to_string(spec.budget) +
                                         " evaluations each",
                                     y),
      dir + "/convergence.png");
  std::vector<render::ParameterAxis> axes;
  const Proven& best = best_proven(o);
  for (std::size_t i = 0; i < spec.parameters.size(); ++i)
    axes.push_back({spec.parameters[i].info.path, spec.parameters[i].lo, spec.parameters[i].hi,
                    spec.parameters[i].info.default_value, best.tuning.values[i]});
  render::write_png(render::draw_parameter_scores(axes, searches, y), dir + "/parameters.png");
}

std::string validation_csv(const TuneSpec& spec, const TuneOutcome& o) {
  std::string csv =
      "setting,found_by,tuning_score,validation_episodes,docked,success_rate,wilson_low,wilson_"
      "high,"
      "mean_time_s,mean_position_error_mm,contacts\n";
  for (const Proven& p : o.proven) {
    const Statistics& s = p.validation.stats;
    csv +=
        p.name + "," + util::csv_field(label(p.name, spec)) + "," + fixed(p.tuning.score.value, 6) +
        "," + std::to_string(s.episodes) + "," + std::to_string(s.succeeded) + "," +
        fixed(s.success_rate, 4) + "," + fixed(s.wilson_low, 4) + "," + fixed(s.wilson_high, 4) +
        "," + optional_text(s.mean_time_s, 1, 2) + "," +
        optional_text(s.mean_position_error_m, 1000, 2) + "," + std::to_string(s.contacts) + "\n";
  }
  return csv;
}

std::string parameter_table_html(const TuneSpec& spec, const TuneOutcome& o) {
  std::string h =
      "<h2>Parameters</h2><table><tr><th>parameter</th><th>searched</th><th>default</th>";
  for (std::size_t k = 1; k < o.proven.size(); ++k)
    h += "<th>" + render::html_escape(label(o.proven[k].name, spec)) + "</th>";
  h += "</tr>";
  for (std::size_t i = 0; i < spec.parameters.size(); ++i) {
    const TunedParameter& p = spec.parameters[i];
    std::ostringstream range;
    range << p.lo << " to " << p.hi;
    h += "<tr><td>" + render::html_escape(p.info.path) + "</td><td>" + range.str() + "</td><td>" +
         fixed(p.info.default_value, 4) + "</td>";
    for (std::size_t k = 1; k < o.proven.size(); ++k)
      h += "<td>" + fixed(o.proven[k].tuning.values[i], 4) + "</td>";
    h += "</tr>";
  }
  return h + "</table>";
}

render::Report report(const TuneSpec& spec, const TuneOutcome& o, const TuneOptions& options,
                      const util::MadeBy& made_by, bool figures) {
  render::Report r;
  r.title = "plantsim tune: " + spec.tuning.name;
  r.command = options.command;
  r.made_by = made_by.text();
  r.banner_html = "<p class=\"verdict\">" + render::html_escape(verdict_text(spec, o)) + "</p>";
  r.headers = {"setting",
               "tuning score (not a verdict)",
               "validation episodes",
               "docked",
               "success rate",
               "Wilson 95 % low",
               "mean time to dock (s)",
               "mean docking error (mm)",
               "contacts"};
  for (const Proven& p : o.proven) {
    const Statistics& s = p.validation.stats;
    r.rows.push_back({label(p.name, spec) + (p.name == o.best ? " (best.json)" : ""),
                      fixed(p.tuning.score.value, 5), std::to_string(s.episodes),
                      std::to_string(s.succeeded), fixed(s.success_rate, 4), fixed(s.wilson_low, 4),
                      optional_text(s.mean_time_s, 1, 1),
                      optional_text(s.mean_position_error_m, 1000, 2), std::to_string(s.contacts)});
  }
  r.notes =
      "Objective (" + objective_name(spec.objective) +
      "): " + objective_description(spec.objective) +
      ". Success floor on the tuning episodes: Wilson low " + fixed(o.floor, 4) + ". " +
      std::to_string(o.tuning_episodes) +
      " tuning episodes per evaluation (the same episodes for every "
      "candidate), " +
      std::to_string(spec.budget) + " evaluations per search, seed " + std::to_string(spec.seed) +
      ". The table's episodes are the validation part only (worlds or seeds no "
      "candidate was judged on); the tuning score is the search's own measure on the tuning part.";
  r.body_html = parameter_table_html(spec, o);
  if (figures) {
    r.figures = {
        {"convergence.png",
         "Best score so far per evaluation: NLopt against random search (tuning episodes)"},
        {"parameters.png",
         "Each evaluation's score against each parameter's value (tuning episodes)"}};
  }
  r.files = {"best.json", "summary.json", "validation.csv", "evaluations.jsonl"};
  return r;
}

}  // namespace

void write_tune_outputs(const TuneSpec& spec, const TuneOutcome& o, const TuneOptions& options,
                        const util::MadeBy& made_by) {
  const std::string& dir = options.out_dir;
  const std::string best =
      nlohmann::json::parse(overrides_json(spec.parameters, best_proven(o).tuning.values)).dump(2);
  util::write_file_atomically(dir + "/best.json", best + "\n");
  util::write_file_atomically(dir + "/validation.csv", validation_csv(spec, o));
  util::write_file_atomically(dir + "/summary.json", summary_json(spec, o, made_by).dump(2) + "\n");
  if (options.figures) write_charts(spec, o, dir);
  render::write_report(report(spec, o, options, made_by, options.figures), dir + "/report.html");
}

}  // namespace plantsim::tune
