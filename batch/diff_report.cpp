// diff.html of plantsim diff: the verdict as a banner, each configuration's tests (worse rows
// first), why, then the changed episodes with the command that re-runs each on both sides and,
// where the batch folders hold them, the two replays side by side.
#include <algorithm>
#include <filesystem>

#include "batch/diff_outputs.h"
#include "render/report.h"
#include "util/fixed_text.h"

namespace plantsim::batch {
namespace {

using render::html_escape;
using util::fixed;

constexpr std::size_t kSideBySide = 12;  ///< changed episodes whose replays are embedded

std::string change_cell(const MetricDiff& m, double scale) {
  if (m.difference.pairs == 0) return "-";
  std::string s = (m.difference.mean >= 0 ? "+" : "") + fixed(m.difference.mean * scale, 2);
  if (m.difference.interval)
    s += " (" + fixed(m.difference.interval->first * scale, 2) + " to " +
         fixed(m.difference.interval->second * scale, 2) + ")";
  if (m.verdict != DiffVerdict::kNoChange) s += " " + std::string(diff_verdict_name(m.verdict));
  return s;
}

std::string outcome_html(const DiffSide& s) {
  if (s.succeeded) return html_escape(s.status) + ", " + fixed(s.time_s, 1) + " s";
  return "<b>" + html_escape(s.reason) + "</b> at " + fixed(s.time_s, 1) + " s" +
         (s.detail.empty() ? "" : "<br><small>" + html_escape(s.detail) + "</small>");
}

/// The replay's path from diff.html's folder, empty when the batch folder holds none.
std::string replay_link(const std::string& folder, const std::string& id,
                        const std::string& out_dir) {
  namespace fs = std::filesystem;
  const std::string replay = diff_replay(folder, id);
  if (replay.empty()) return "";
  const fs::path target = fs::absolute(fs::path(folder) / replay).lexically_normal();
  return target.lexically_relative(fs::absolute(out_dir).lexically_normal()).string();
}

std::string side_cell(const DiffSide& s, const std::string& folder, const std::string& id,
                      const std::string& out_dir) {
  const std::string link = replay_link(folder, id, out_dir);
  return "<code style=\"word-break:break-all\">" + html_escape(diff_rerun_command(s, folder, id)) +
         "</code>" +
         (link.empty() ? "<br><small>no replay in the folder yet: the command writes one to " +
                             html_escape(folder) + "/episodes/</small>"
                       : "<br><a href=\"" + render::url_attribute(link) + "\">replay</a>");
}

std::string banner(const BatchDiff& d) {
  std::vector<std::string> names;
  for (const ConfigurationDiff& c : d.configurations)
    if (c.verdict == d.verdict) names.push_back(c.name());
  const std::string cls = d.verdict == DiffVerdict::kWorse ? "fail" : "pass";
  std::string h = "<div class=\"banner " + cls + "\"><b>";
  for (char c : std::string(diff_verdict_name(d.verdict)))
    h += static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  h += "</b>: ";
  if (d.verdict == DiffVerdict::kNoChange) {
    h += "no configuration changed detectably at level " + fixed(d.level, 3) + " (" +
         std::to_string(d.paired) + " episodes in both, " + std::to_string(d.lost) + " lost, " +
         std::to_string(d.gained) + " gained). McNemar's exact test needs at least " +
         std::to_string(mcnemar_smallest_detectable(d.level)) +
         " episodes of a configuration changed, all one way, to show anything.";
  } else {
    h += std::to_string(names.size()) + " of " + std::to_string(d.configurations.size()) +
         " configurations " + diff_verdict_name(d.verdict) + ": ";
    for (std::size_t i = 0; i < names.size() && i < 10; ++i)
      h += (i ? "; " : "") + html_escape(names[i]);
    if (names.size() > 10) h += "; ...";
    h += " (" + std::to_string(d.lost) + " episodes lost, " + std::to_string(d.gained) +
         " gained of " + std::to_string(d.paired) + ").";
  }
  return h + "</div>\n";
}

std::string side_by_side(const BatchDiff& d, const std::string& out_dir) {
  std::string h;
  std::size_t shown = 0;
  for (const ChangedEpisode& e : d.changed) {
    if (shown >= kSideBySide) break;
    const std::string left = replay_link(d.baseline.folder, e.id, out_dir);
    const std::string right = replay_link(d.candidate.folder, e.id, out_dir);
    if (left.empty() && right.empty()) continue;
    ++shown;
    h += "<h3>" + html_escape(e.id) + " (" + (e.gained ? "gained" : "lost") +
         ")</h3>\n<div style=\"display:flex;gap:8px\">";
    for (const auto& [label, link] : {std::pair<std::string, std::string>{"baseline", left},
                                      std::pair<std::string, std::string>{"candidate", right}}) {
      h += "<div style=\"flex:1;min-width:0\"><p>" + label + "</p>";
      h += link.empty()
               ? "<p>no replay in this folder</p>"
               : "<iframe loading=\"lazy\" src=\"" + render::url_attribute(link) +
                     "\" style=\"width:100%;height:560px;border:1px solid #bbb\" title=\"" + label +
                     " replay of " + html_escape(e.id) + "\"></iframe>";
      h += "</div>";
    }
    h += "</div>\n";
  }
  if (shown == 0) return "";
  return "<h2>Replays side by side</h2>\n<p>The first " + std::to_string(shown) +
         " changed episodes with a replay in either folder (a failure gallery's, or one made by "
         "the re-run command).</p>\n" +
         h;
}

}  // namespace

std::string diff_html(const BatchDiff& d, const util::MadeBy& made_by, const std::string& command,
                      const std::string& out_dir) {
  render::Report r;
  r.title = "plantsim diff: " + d.baseline.folder + " against " + d.candidate.folder;
  r.made_by = made_by.text();
  r.command = command;
  r.banner_html = banner(d);
  r.notes = "Baseline " + d.baseline.folder + ": " + std::to_string(d.baseline.records) +
            " records; candidate " + d.candidate.folder + ": " +
            std::to_string(d.candidate.records) + " records; " + std::to_string(d.paired) +
            " episodes in both, " + std::to_string(d.only_baseline) + " only in the baseline and " +
            std::to_string(d.only_candidate) +
            " only in the candidate (not compared). Changes are candidate minus baseline, on the "
            "episodes both succeeded in, with their " +
            fixed(100 * (1 - d.level), 0) +
            " % interval; McNemar's exact test on the episodes "
            "one side succeeded in. The rule: docs/batch.md, \"Did my change make it worse?\".";
  r.headers = {
      "configuration", "verdict", "episodes",  "baseline succeeded", "candidate succeeded",
      "lost",          "gained",  "McNemar p", "time change s",      "position error change mm"};
  std::vector<const ConfigurationDiff*> rows;
  for (const ConfigurationDiff& c : d.configurations) rows.push_back(&c);
  std::stable_sort(rows.begin(), rows.end(), [](const auto* a, const auto* b) {
    return (a->verdict == DiffVerdict::kWorse) > (b->verdict == DiffVerdict::kWorse);
  });
  for (const ConfigurationDiff* c : rows) {
    r.rows.push_back({c->name(), diff_verdict_name(c->verdict), std::to_string(c->pairs),
                      std::to_string(c->baseline_succeeded), std::to_string(c->candidate_succeeded),
                      std::to_string(c->lost), std::to_string(c->gained), fixed(c->mcnemar_p, 4),
                      change_cell(c->time, 1), change_cell(c->error, 1000)});
    r.row_classes.push_back(c->verdict == DiffVerdict::kWorse ? "fail" : "");
  }
  std::string why;
  for (const ConfigurationDiff* c : rows)
    for (const std::string& w : c->why)
      why += "<li>" + html_escape(c->name()) + ": " + html_escape(w) + "</li>\n";
  if (!why.empty()) r.body_html += "<h2>Why</h2>\n<ul>\n" + why + "</ul>\n";
  if (!d.changed.empty()) {
    r.body_html += "<h2>Changed episodes (" + std::to_string(d.changed.size()) + ")</h2>\n";
    if (d.changed.size() > kDiffHtmlChanged)
      r.body_html += "<p>The first " + std::to_string(kDiffHtmlChanged) +
                     "; diff.json lists up to " + std::to_string(kDiffJsonChanged) + ".</p>\n";
    r.body_html +=
        "<table style=\"table-layout:fixed;width:100%\"><tr><th class=\"l\" "
        "style=\"width:16%\">episode</th><th class=\"l\" style=\"width:6%\">change</th><th "
        "class=\"l\" style=\"width:12%\">baseline</th><th class=\"l\" "
        "style=\"width:12%\">candidate</th><th class=\"l\">re-run in the baseline</th><th "
        "class=\"l\">re-run in the candidate</th></tr>\n";
    for (std::size_t i = 0; i < d.changed.size() && i < kDiffHtmlChanged; ++i) {
      const ChangedEpisode& e = d.changed[i];
      r.body_html += std::string(e.gained ? "<tr>" : "<tr class=\"fail\">") +
                     "<td class=\"l\" style=\"word-break:break-all\">" + html_escape(e.id) +
                     "</td><td class=\"l\">" + (e.gained ? "gained" : "lost") +
                     "</td><td class=\"l\">" + outcome_html(e.baseline) + "</td><td class=\"l\">" +
                     outcome_html(e.candidate) + "</td><td class=\"l\">" +
                     side_cell(e.baseline, d.baseline.folder, e.id, out_dir) +
                     "</td><td class=\"l\">" +
                     side_cell(e.candidate, d.candidate.folder, e.id, out_dir) + "</td></tr>\n";
    }
    r.body_html += "</table>\n" + side_by_side(d, out_dir);
  }
  r.files = {"diff.json", "diff.md"};
  return render::report_html(r);
}

}  // namespace plantsim::batch
