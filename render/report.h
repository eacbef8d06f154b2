// A static, offline HTML report: title, the command that produced it, a metrics table, the
// figures (relative links to PNG files beside it), optional embedded HTML (a replay) and links
// to the raw files. No network: it opens from disk anywhere. A small script marks on the page
// whether every image loaded (data-images-loaded on <html>), for browser tests.
#pragma once

#include <string>
#include <vector>

namespace plantsim::render {

struct ReportFigure {
  std::string file;  ///< relative to the report
  std::string caption;
};

/// A further table of a report, under its own heading.
struct ReportTable {
  std::string heading;
  std::vector<std::string> headers;
  std::vector<std::vector<std::string>> rows;
};

struct Report {
  std::string title;
  std::string command;
  std::vector<std::string> headers;
  std::vector<std::vector<std::string>> rows;
  std::vector<ReportTable> more_tables;  ///< after the first table, each under its heading
  std::vector<ReportFigure> figures;
  std::vector<std::string> files;  ///< other outputs to link (CSV, JSON)
  std::string notes;               ///< a paragraph of plain text
  std::string body_html;           ///< trusted HTML placed before the figures (a replay player)
  std::string made_by;  ///< which build made it, when, from what (util/made_by.h), under the title
  std::string banner_html;               ///< trusted HTML first under the title (a batch's verdict)
  std::vector<std::string> row_classes;  ///< per row, may be shorter: "fail" draws it red
  /// per figure, may be shorter: a page the figure links to (a failed episode's replay)
  std::vector<std::string> figure_links;
};

std::string report_html(const Report& r);
/// Text made safe inside HTML elements and attribute values.
std::string html_escape(const std::string& s);
/// A relative file path as an attribute's URL: every byte but letters, digits, '-', '.', '_',
/// '~' and '/' percent-encoded ('#', '%', '?' and spaces in a world's name broke image links).
std::string url_attribute(const std::string& relative_path);
/// The script that marks <html data-images-loaded="all N"> (or "missing: ...") once loaded.
std::string image_check_script();
/// Written atomically to `path`.
void write_report(const Report& r, const std::string& path);

/// Every relative file the HTML references (src= and href=, percent-decoded), for checks.
std::vector<std::string> referenced_files(const std::string& html);

}  // namespace plantsim::render
