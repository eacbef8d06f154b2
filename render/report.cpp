// HTML generation with escaping.
#include "render/report.h"

#include <cctype>
#include <string>

#include "util/atomic_file.h"

namespace plantsim::render {
std::string html_escape(const std::string& s) {
  std::string out;
  for (char c : s) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

std::string url_attribute(const std::string& relative_path) {
  std::string out;
  for (const char c : relative_path) {
    const auto b = static_cast<unsigned char>(c);
    if (std::isalnum(b) || c == '-' || c == '.' || c == '_' || c == '~' || c == '/') {
      out += c;
    } else {
      static constexpr char kHex[] = "0123456789ABCDEF";
      out += {'%', kHex[b >> 4], kHex[b & 15]};
    }
  }
  return out;
}

std::string image_check_script() {
  return "<script>window.addEventListener('load', function () {\n"
         "  const bad = Array.from(document.images).filter(i => !i.complete || i.naturalWidth === "
         "0).map(i => i.src);\n"
         "  document.documentElement.dataset.imagesLoaded = bad.length ? 'missing: ' + bad.join(' "
         "') : 'all ' + "
         "document.images.length;\n"
         "  document.documentElement.dataset.pageWidth = document.documentElement.scrollWidth;\n"
         "});</script>\n";
}

std::string report_html(const Report& r) {
  std::string h =
      "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>" +
      html_escape(r.title) +
      "</title>\n<style>body{font-family:DejaVu Sans,sans-serif;margin:24px;color:#222}"
      "table{border-collapse:collapse;margin:12px 0;font-size:14px}td,th{border:1px solid #bbb;"
      "padding:3px 6px;"
      "text-align:right}th{background:#eee}td:first-child,th:first-child,td.l,th.l{text-align:left}"
      "img{max-width:100%;border:1px solid #ddd;margin:8px 0}code{background:#f4f4f4;padding:2px "
      "4px}"
      "figure{margin:16px 0}tr.fail td{color:#c03c00;font-weight:bold}"
      ".banner{padding:8px 12px;margin:12px 0;background:#f6f6f6;border-left:8px solid #999}"
      ".banner.pass{border-color:#009e73}.banner.fail{border-color:#d55e00}"
      ".banner.mixed{border-color:#e69f00}</style></head><body>\n";
  h += "<h1>" + html_escape(r.title) + "</h1>\n";
  if (!r.made_by.empty())
    h += "<p class=\"made-by\" style=\"color:#555\">" + html_escape(r.made_by) + "</p>\n";
  h += r.banner_html;
  if (!r.command.empty()) h += "<p>Produced by <code>" + html_escape(r.command) + "</code></p>\n";
  if (!r.notes.empty()) h += "<p>" + html_escape(r.notes) + "</p>\n";
  if (!r.headers.empty()) {
    h += "<table><tr>";
    for (const auto& c : r.headers) h += "<th>" + html_escape(c) + "</th>";
    h += "</tr>\n";
    for (std::size_t i = 0; i < r.rows.size(); ++i) {
      const auto& row = r.rows[i];
      h += i < r.row_classes.size() && !r.row_classes[i].empty()
               ? "<tr class=\"" + html_escape(r.row_classes[i]) + "\">"
               : std::string("<tr>");
      for (const auto& c : row) h += "<td>" + html_escape(c) + "</td>";
      h += "</tr>\n";
    }
    h += "</table>\n";
  }
  for (const ReportTable& t : r.more_tables) {
    h += "<h2>" + html_escape(t.heading) + "</h2>\n<table><tr>";
    for (const auto& c : t.headers) h += "<th>" + html_escape(c) + "</th>";
    h += "</tr>\n";
    for (const auto& row : t.rows) {
      h += "<tr>";
      for (const auto& c : row) h += "<td>" + html_escape(c) + "</td>";
      h += "</tr>\n";
    }
    h += "</table>\n";
  }
  h += r.body_html;
  for (std::size_t i = 0; i < r.figures.size(); ++i) {
    const ReportFigure& f = r.figures[i];
    const std::string link = i < r.figure_links.size() ? r.figure_links[i] : "";
    const std::string img =
        "<img src=\"" + url_attribute(f.file) + "\" alt=\"" + html_escape(f.caption) + "\">";
    h += "<figure>" +
         (link.empty() ? img : "<a href=\"" + url_attribute(link) + "\">" + img + "</a>") +
         "<figcaption>" + html_escape(f.caption) +
         (link.empty() ? "" : " <a href=\"" + url_attribute(link) + "\">Replay it</a>") +
         "</figcaption></figure>\n";
  }
  if (!r.files.empty()) {
    h += "<p>Files: ";
    for (std::size_t i = 0; i < r.files.size(); ++i)
      h += (i ? ", " : "") + std::string("<a href=\"") + url_attribute(r.files[i]) + "\">" +
           html_escape(r.files[i]) + "</a>";
    h += "</p>\n";
  }
  h += image_check_script();
  h += "</body></html>\n";
  return h;
}

void write_report(const Report& r, const std::string& path) {
  util::write_file_atomically(path, report_html(r));
}

std::vector<std::string> referenced_files(const std::string& html) {
  std::vector<std::string> out;
  for (const std::string attribute : {"src=\"", "href=\""}) {
    for (std::size_t at = html.find(attribute); at != std::string::npos;
         at = html.find(attribute, at + 1)) {
      const std::size_t begin = at + attribute.size(), end = html.find('"', begin);
      if (end == std::string::npos) continue;
      std::string file;
      for (std::size_t i = begin; i < end; ++i)
        if (html[i] == '%' && i + 2 < end) {
          file += static_cast<char>(std::stoi(html.substr(i + 1, 2), nullptr, 16));
          i += 2;
        } else {
          file += html[i];
        }
      out.push_back(file);
    }
  }
  return out;
}

}  // namespace plantsim::render
