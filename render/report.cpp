// HTML generation with escaping.
#include "render/report.h"


#include "util/atomic_file.h"

namespace plantsim::render {
namespace {

std::string escape(const std::string& s) {
  std::string out;
  for (char c : s) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      default: out += c;
    }
  }
  return out;
}

}  // namespace

std::string report_html(const Report& r) {
  std::string h = "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>" + escape(r.title) +
                  "</title>\n<style>body{font-family:DejaVu Sans,sans-serif;margin:24px;color:#222}"
                  "table{border-collapse:collapse;margin:12px 0}td,th{border:1px solid #bbb;padding:4px 8px;"
                  "text-align:right}th{background:#eee}td:first-child,th:first-child{text-align:left}"
                  "img{max-width:100%;border:1px solid #ddd;margin:8px 0}code{background:#f4f4f4;padding:2px 4px}"
                  "figure{margin:16px 0}</style></head><body>\n";
  h += "<h1>" + escape(r.title) + "</h1>\n";
  if (!r.command.empty()) h += "<p>Produced by <code>" + escape(r.command) + "</code></p>\n";
  if (!r.notes.empty()) h += "<p>" + escape(r.notes) + "</p>\n";
  if (!r.headers.empty()) {
    h += "<table><tr>";
    for (const auto& c : r.headers) h += "<th>" + escape(c) + "</th>";
    h += "</tr>\n";
    for (const auto& row : r.rows) {
      h += "<tr>";
      for (const auto& c : row) h += "<td>" + escape(c) + "</td>";
      h += "</tr>\n";
    }
    h += "</table>\n";
  }
  for (const auto& f : r.figures)
    h += "<figure><img src=\"" + escape(f.file) + "\" alt=\"" + escape(f.caption) + "\"><figcaption>" +
         escape(f.caption) + "</figcaption></figure>\n";
  if (!r.files.empty()) {
    h += "<p>Files: ";
    for (std::size_t i = 0; i < r.files.size(); ++i)
      h += (i ? ", " : "") + std::string("<a href=\"") + escape(r.files[i]) + "\">" + escape(r.files[i]) + "</a>";
    h += "</p>\n";
  }
  h += "</body></html>\n";
  return h;
}

void write_report(const Report& r, const std::string& path) { util::write_file_atomically(path, report_html(r)); }

std::vector<std::string> referenced_files(const std::string& html) {
  std::vector<std::string> out;
  for (const std::string attribute : {"src=\"", "href=\""}) {
    for (std::size_t at = html.find(attribute); at != std::string::npos; at = html.find(attribute, at + 1)) {
      const std::size_t begin = at + attribute.size(), end = html.find('"', begin);
      if (end != std::string::npos) out.push_back(html.substr(begin, end - begin));
    }
  }
  return out;
}

}  // namespace plantsim::render
