// The dashboard's HTML, escaped, with the same image-load marker as the reports.
#include "render/dashboard.h"

#include "render/overall_verdict.h"
#include "render/report.h"
#include "util/fixed_text.h"

namespace plantsim::render {
namespace {

using util::fixed;

std::string path_of(const std::string& folder, const std::string& file) {
  return folder.empty() || folder == "." ? file : folder + "/" + file;
}

/// The dashboard's own stamp, and how many of its outputs another build made.
std::string stamp_paragraph(const std::vector<DashboardRun>& runs,
                            const std::vector<DashboardLink>& links, const std::string& made_by) {
  int stale = 0;
  for (const auto& r : runs) stale += !r.stale.empty();
  for (const auto& l : links) stale += !l.stale.empty();
  if (made_by.empty() && stale == 0) return "";
  std::string h = "<p class=\"made-by\" style=\"color:#555\">" + html_escape(made_by);
  if (stale > 0)
    h += " <span class=\"bad\">" + std::to_string(stale) +
         " of the outputs below were not made by this build (flagged): run them again.</span>";
  return h + "</p>\n";
}

/// A batch's last runs as a small inline chart: each run's success rate a dot (green passed,
/// vermillion failed, grey not gated) joined by a line, the oldest left; the dates and commits in
/// its title, the verdicts written under it.
std::string trend_svg(const std::vector<TrendPoint>& trend) {
  if (trend.empty()) return "";
  constexpr double kWidth = 180, kHeight = 40, kPad = 6;
  const std::size_t n = trend.size();
  auto x = [&](std::size_t i) {
    return n == 1 ? kWidth / 2 : kPad + (kWidth - 2 * kPad) * i / (n - 1.0);
  };
  auto y = [&](const TrendPoint& p) {
    const double rate = p.episodes > 0 ? static_cast<double>(p.succeeded) / p.episodes : 0.0;
    return kHeight - kPad - (kHeight - 2 * kPad) * rate;
  };
  std::string title, line, dots, verdicts;
  for (std::size_t i = 0; i < n; ++i) {
    const TrendPoint& p = trend[i];
    const std::string colour = p.verdict == "passed"   ? "#009e73"
                               : p.verdict == "failed" ? "#d55e00"
                                                       : "#888888";
    line += (i ? " " : "") + fixed(x(i), 1) + "," + fixed(y(p), 1);
    dots += "<circle cx=\"" + fixed(x(i), 1) + "\" cy=\"" + fixed(y(p), 1) +
            "\" r=\"3.5\" fill=\"" + colour + "\"/>";
    title += p.date + " " + p.commit + ": " + p.verdict + ", " + std::to_string(p.succeeded) + "/" +
             std::to_string(p.episodes) + "\n";
    verdicts += std::string(i ? " " : "") + (p.verdict == "passed"   ? "PASS"
                                             : p.verdict == "failed" ? "FAIL"
                                                                     : "-");
  }
  return "<div class=\"trend\"><svg width=\"" + fixed(kWidth, 0) + "\" height=\"" +
         fixed(kHeight, 0) + "\" role=\"img\"><title>" + html_escape(title) +
         "</title><polyline points=\"" + line + "\" fill=\"none\" stroke=\"#999\"/>" + dots +
         "</svg><br>last " + std::to_string(n) + " runs: " + verdicts + "</div>";
}

/// One linked report's row: thumbnail, title, a batch's verdict, what is said of it.
std::string link_row(const DashboardLink& l) {
  std::string row = "<tr><td class=\"l\">";
  if (!l.thumbnail.empty())
    row += "<a href=\"" + url_attribute(l.report) + "\"><img class=\"thumb\" src=\"" +
           url_attribute(l.thumbnail) + "\" alt=\"" + html_escape(l.title) + "\"></a>";
  row += "</td><td class=\"l\"><a href=\"" + url_attribute(l.report) + "\">" +
         html_escape(l.title) + "</a></td>";
  if (l.kind == "batch")
    row += "<td class=\"l " +
           std::string(l.verdict == "passed"   ? "ok"
                       : l.verdict == "failed" ? "bad"
                                               : "") +
           "\">" + html_escape(l.verdict.empty() ? "no verdict" : "gate " + l.verdict) +
           trend_svg(l.trend) + "</td>";
  return row + "<td class=\"l\">" + html_escape(l.line) +
         (l.stale.empty() ? "" : "<span class=\"stale\">" + html_escape(l.stale) + "</span>") +
         "</td></tr>\n";
}

/// The verdict first, what a team lead reads before anything else (render/overall_verdict.h).
std::string verdict_banner(const OverallVerdict& v) {
  const char* css = v.kind == OverallVerdict::Kind::kFail   ? "fail"
                    : v.kind == OverallVerdict::Kind::kPass ? "pass"
                                                            : "none";
  return "<div class=\"banner " + std::string(css) + "\"><b>" + v.word +
         "</b>: " + html_escape(v.why) + "</div>\n";
}

}  // namespace

std::string dashboard_html(const std::string& title, const std::vector<std::string>& headers,
                           const std::vector<DashboardRun>& runs,
                           const std::vector<DashboardLink>& links, const std::string& made_by) {
  std::string h =
      "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>" +
      html_escape(title) +
      "</title>\n<style>body{font-family:DejaVu Sans,sans-serif;margin:24px;color:#222}"
      "table{border-collapse:collapse;margin:12px 0;font-size:14px}td,th{border:1px solid #bbb;"
      "padding:3px 6px;text-align:right;vertical-align:middle}th{background:#eee}"
      "td.l,th.l{text-align:left}.files{font-size:12px;color:#555}"
      "img.thumb{width:180px;border:1px solid #ddd}.ok{color:#007a56;font-weight:bold}"
      ".bad{color:#c03c00;font-weight:bold}.stale{color:#c03c00;display:block}"
      ".banner{padding:8px 12px;margin:12px 0;background:#f6f6f6;border-left:8px solid #999}"
      ".banner.pass{border-color:#009e73}.banner.fail{border-color:#d55e00}</style></"
      "head><body>\n";
  int ok = 0;
  for (const auto& r : runs) ok += r.succeeded;
  // Runs and batches are counted apart: a batch's failures are its episodes', judged by its gate.
  int batches = 0, passed = 0, failed = 0;
  for (const auto& l : links)
    if (l.kind == "batch")
      ++batches, passed += l.verdict == "passed", failed += l.verdict == "failed";
  h += "<h1>" + html_escape(title) + "</h1>\n" + stamp_paragraph(runs, links, made_by);
  h += verdict_banner(overall_verdict(runs, links));
  h += "<p>" + std::to_string(ok) + " of " + std::to_string(runs.size()) + " single runs succeeded";
  if (batches > 0)
    h += "; of " + std::to_string(batches) + " batches, " + std::to_string(passed) +
         " passed their gates, <span class=\"" + (failed ? "bad" : "ok") + "\">" +
         std::to_string(failed) + " failed</span>, " + std::to_string(batches - passed - failed) +
         " not gated (below: each batch's episodes, failures by reason and gate)";
  h += ". Click a thumbnail for its report (figures, replay, files).</p>\n";
  h += "<h2>Runs</h2>\n<table><tr><th class=\"l\">figure</th><th class=\"l\">world</th><th "
       "class=\"l\">setting</th>"
       "<th class=\"l\">status</th>";
  for (const auto& c : headers) h += "<th>" + html_escape(c) + "</th>";
  h += "</tr>\n";
  for (const auto& r : runs) {
    const std::string report = path_of(r.folder, "report.html");
    h += "<tr><td class=\"l\">";
    if (!r.figures.empty())
      h += "<a href=\"" + url_attribute(report) + "\"><img class=\"thumb\" src=\"" +
           url_attribute(path_of(r.folder, r.figures.front())) + "\" alt=\"" +
           html_escape(r.world) + "\"></a>";
    // The run's files under its world's name: a column of their own made the table wider than
    // a 1,400-pixel screen.
    h += "</td><td class=\"l\"><a href=\"" + url_attribute(report) + "\">" + html_escape(r.world) +
         "</a><div class=\"files\">";
    for (std::size_t i = 0; i < r.figures.size(); ++i)
      h += (i ? ", " : "") + std::string("<a href=\"") +
           url_attribute(path_of(r.folder, r.figures[i])) + "\">" + html_escape(r.figures[i]) +
           "</a>";
    h += "</div></td><td class=\"l\">" + html_escape(r.setting) + "</td><td class=\"l " +
         (r.succeeded ? "ok" : "bad") + "\">" + html_escape(r.status) +
         (r.stale.empty() ? "" : "<span class=\"stale\">" + html_escape(r.stale) + "</span>") +
         "</td>";
    for (const auto& c : r.cells) h += "<td>" + html_escape(c) + "</td>";
    h += "</tr>\n";
  }
  h += "</table>\n";
  for (const std::string kind : {"comparison", "batch", "tune", "coverage", "chart", "report"}) {
    std::string rows;
    for (const auto& l : links)
      if (l.kind == kind) rows += link_row(l);
    if (rows.empty()) continue;
    const std::string heading = kind == "comparison" ? "Comparisons"
                                : kind == "batch"    ? "Batches"
                                : kind == "tune"     ? "Tunings"
                                : kind == "coverage" ? "Coverage"
                                : kind == "chart"    ? "Charts"
                                                     : "Other reports";
    h += "<h2>" + heading + "</h2>\n<table>" + rows + "</table>\n";
  }
  h += image_check_script() + "</body></html>\n";
  return h;
}

}  // namespace plantsim::render
