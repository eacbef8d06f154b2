// A static, offline HTML report: title, the command that produced it, a metrics table, the
// figures (relative links to PNG files beside it) and links to the raw files. No scripts,
// no network: it opens from disk anywhere.
#pragma once

#include <string>
#include <vector>

namespace plantsim::render {

struct ReportFigure {
  std::string file;     ///< relative to the report
  std::string caption;
};

struct Report {
  std::string title;
  std::string command;
  std::vector<std::string> headers;
  std::vector<std::vector<std::string>> rows;
  std::vector<ReportFigure> figures;
  std::vector<std::string> files;  ///< other outputs to link (CSV, JSON)
  std::string notes;               ///< a paragraph of plain text
};

std::string report_html(const Report& r);
/// Written atomically to `path`.
void write_report(const Report& r, const std::string& path);

/// Every relative file the HTML references (src= and href=), for checks.
std::vector<std::string> referenced_files(const std::string& html);

}  // namespace plantsim::render
