// The dashboard's HTML, escaped, with the same image-load marker as the reports.
#include "render/dashboard.h"

#include "render/report.h"

namespace plantsim::render {
namespace {

std::string path_of(const std::string& folder, const std::string& file) {
  return folder.empty() || folder == "." ? file : folder + "/" + file;
}

}  // namespace

std::string dashboard_html(const std::string& title, const std::vector<std::string>& headers,
                           const std::vector<DashboardRun>& runs,
                           const std::vector<DashboardLink>& links) {
  std::string h =
      "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>" +
      html_escape(title) +
      "</title>\n<style>body{font-family:DejaVu Sans,sans-serif;margin:24px;color:#222}"
      "table{border-collapse:collapse;margin:12px 0}td,th{border:1px solid #bbb;padding:4px 8px;"
      "text-align:right;vertical-align:middle}th{background:#eee}td.l,th.l{text-align:left}"
      "img.thumb{width:220px;border:1px solid #ddd}.ok{color:#007a56;font-weight:bold}"
      ".bad{color:#c03c00;font-weight:bold}</style></head><body>\n";
  int ok = 0;
  for (const auto& r : runs) ok += r.succeeded;
  // Runs and batches are counted apart: a batch's failures are its episodes', judged by its gate.
  int batches = 0, passed = 0, failed = 0;
  for (const auto& l : links)
    if (l.kind == "batch")
      ++batches, passed += l.verdict == "passed", failed += l.verdict == "failed";
  h += "<h1>" + html_escape(title) + "</h1>\n<p>" + std::to_string(ok) + " of " +
       std::to_string(runs.size()) + " single runs succeeded";
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
  h += "<th class=\"l\">files</th></tr>\n";
  for (const auto& r : runs) {
    const std::string report = path_of(r.folder, "report.html");
    h += "<tr><td class=\"l\">";
    if (!r.figures.empty())
      h += "<a href=\"" + url_attribute(report) + "\"><img class=\"thumb\" src=\"" +
           url_attribute(path_of(r.folder, r.figures.front())) + "\" alt=\"" +
           html_escape(r.world) + "\"></a>";
    h += "</td><td class=\"l\"><a href=\"" + url_attribute(report) + "\">" + html_escape(r.world) +
         "</a></td><td class=\"l\">" + html_escape(r.setting) + "</td><td class=\"l " +
         (r.succeeded ? "ok" : "bad") + "\">" + html_escape(r.status) + "</td>";
    for (const auto& c : r.cells) h += "<td>" + html_escape(c) + "</td>";
    h += "<td class=\"l\">";
    for (std::size_t i = 0; i < r.figures.size(); ++i)
      h += (i ? ", " : "") + std::string("<a href=\"") +
           url_attribute(path_of(r.folder, r.figures[i])) + "\">" + html_escape(r.figures[i]) +
           "</a>";
    h += "</td></tr>\n";
  }
  h += "</table>\n";
  for (const std::string kind : {"comparison", "batch", "coverage", "chart", "report"}) {
    std::string rows;
    for (const auto& l : links) {
      if (l.kind != kind) continue;
      rows += "<tr><td class=\"l\">";
      if (!l.thumbnail.empty())
        rows += "<a href=\"" + url_attribute(l.report) + "\"><img class=\"thumb\" src=\"" +
                url_attribute(l.thumbnail) + "\" alt=\"" + html_escape(l.title) + "\"></a>";
      rows += "</td><td class=\"l\"><a href=\"" + url_attribute(l.report) + "\">" +
              html_escape(l.title) + "</a></td>";
      if (kind == std::string("batch"))
        rows += "<td class=\"l " +
                std::string(l.verdict == "passed"   ? "ok"
                            : l.verdict == "failed" ? "bad"
                                                    : "") +
                "\">" + html_escape(l.verdict.empty() ? "no verdict" : "gate " + l.verdict) +
                "</td>";
      rows += "<td class=\"l\">" + html_escape(l.line) + "</td></tr>\n";
    }
    if (rows.empty()) continue;
    const std::string heading = kind == "comparison" ? "Comparisons"
                                : kind == "batch"    ? "Batches"
                                : kind == "coverage" ? "Coverage"
                                : kind == "chart"    ? "Charts"
                                                     : "Other reports";
    h += "<h2>" + heading + "</h2>\n<table>" + rows + "</table>\n";
  }
  h += image_check_script() + "</body></html>\n";
  return h;
}

}  // namespace plantsim::render
