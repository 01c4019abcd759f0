#include "reports/html_writer.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace spifit::reports {

std::string html_escape(const std::string& s) {
  std::string out;
  for (char c : s) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&#39;"; break;
      default: out += c;
    }
  }
  return out;
}

namespace {

// The style sheet of every report (a long constant, kept in one piece).
const char* const kCss = R"(body{font-family:system-ui,-apple-system,"Segoe UI",Roboto,Helvetica,Arial,sans-serif;max-width:1100px;margin:2em auto;padding:0 1.2em;color:#222;line-height:1.45}
h1{border-bottom:2px solid #444;padding-bottom:.2em}h2{margin-top:1.8em;border-bottom:1px solid #ccc;padding-bottom:.15em}
table{border-collapse:collapse;margin:.8em 0;font-size:.92em}th,td{border:1px solid #ccc;padding:.3em .6em;vertical-align:top}
th{background:#f0f0f0;text-align:left}td.num{text-align:right;font-variant-numeric:tabular-nums;white-space:nowrap}
td.bad{background:#fdecea;color:#a50e0e;font-weight:bold}td.warn{background:#fff8e1}td.good{color:#1b5e20}td.diag{background:#eee;color:#777}
.callout{border-left:6px solid;padding:.5em 1em;margin:1em 0;border-radius:3px}.callout p{margin:.2em 0;font-weight:bold}
.callout ul{margin:.3em 0 .2em 1.2em;padding:0}.callout.warn{border-color:#c62828;background:#fdecea}.callout.note{border-color:#f9a825;background:#fffde7}
.callout.ok{border-color:#2e7d32;background:#e8f5e9}figure{margin:1em 0}figure img{max-width:100%;border:1px solid #ddd}
figcaption{font-size:.85em;color:#555}code{background:#f4f4f4;padding:0 .2em;border-radius:2px})";

const char* css_class(CellStyle s) {
  switch (s) {
    case CellStyle::good: return "good";
    case CellStyle::warn: return "warn";
    case CellStyle::bad: return "bad";
    case CellStyle::diagonal: return "diag";
    case CellStyle::plain: break;
  }
  return "";
}

const char* css_class(CalloutKind k) {
  switch (k) {
    case CalloutKind::warning: return "warn";
    case CalloutKind::note: return "note";
    case CalloutKind::ok: return "ok";
  }
  return "";
}

std::string html_inline(const Inline& spans) {
  std::string out;
  for (const auto& s : spans) {
    std::string t = html_escape(s.text);
    if (s.code) t = "<code>" + t + "</code>";
    if (!s.href.empty()) t = "<a href=\"" + html_escape(s.href) + "\">" + t + "</a>";
    if (s.bold) t = "<strong>" + t + "</strong>";
    out += t;
  }
  return out;
}

std::string html_items(const std::vector<Inline>& items) {
  std::string h = "<ul>\n";
  for (const auto& it : items) h += "<li>" + html_inline(it) + "</li>\n";
  return h + "</ul>\n";
}

std::string html_cell(const Cell& c, bool numeric) {
  std::string cls = numeric ? "num" : "";
  const std::string style_class = css_class(c.style);
  if (!style_class.empty()) cls += (cls.empty() ? "" : " ") + style_class;
  std::string style;
  if (std::isfinite(c.shade) && c.style == CellStyle::plain) {
    char buf[96];
    const double a = std::min(1.0, std::abs(c.shade)) * 0.75;
    std::snprintf(buf, sizeof buf, " style=\"background:rgba(%s,%.2f)\"", c.shade >= 0 ? "31,119,180" : "214,39,40", a);
    style = buf;
  }
  return "<td" + (cls.empty() ? std::string() : " class=\"" + cls + "\"") + style + ">" + html_escape(c.text) + "</td>";
}

std::string html_table(const Table& t) {
  std::string h = "<table" + (t.id.empty() ? std::string() : " id=\"" + html_escape(t.id) + "\"") + ">\n<thead>\n<tr>";
  for (const auto& c : t.header) h += "<th>" + html_escape(c) + "</th>";
  h += "</tr>\n</thead>\n<tbody>\n";
  for (const auto& row : t.rows) {
    h += "<tr>";
    for (std::size_t k = 0; k < row.size(); ++k) h += html_cell(row[k], k < t.right.size() && t.right[k]);
    h += "</tr>\n";
  }
  return h + "</tbody>\n</table>\n";
}

std::string html_block(const Block& b) {
  switch (b.kind) {
    case Block::Kind::heading: {
      std::string tag = "h";
      tag += std::to_string(b.level);
      const std::string id = b.anchor.empty() ? std::string() : " id=\"" + html_escape(b.anchor) + "\"";
      return "<" + tag + id + ">" + html_inline(b.text) + "</" + tag + ">\n";
    }
    case Block::Kind::paragraph: return "<p>" + html_inline(b.text) + "</p>\n";
    case Block::Kind::callout:
      return "<div class=\"callout " + std::string(css_class(b.callout)) + "\">\n<p>" + html_escape(b.title) + "</p>\n" +
             html_items(b.items) + "</div>\n";
    case Block::Kind::list: return html_items(b.items);
    case Block::Kind::figure:
      return "<figure>\n<img src=\"" + html_escape(b.src) + "\" alt=\"" + html_escape(b.alt) + "\">\n<figcaption>" +
             html_escape(b.alt) + "</figcaption>\n</figure>\n";
    case Block::Kind::table: return html_table(b.table);
  }
  return {};
}

}  // namespace

std::string to_html(const Document& doc) {
  std::string h = "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>" + html_escape(doc.title) +
                  "</title>\n<style>\n" + kCss + "\n</style>\n</head>\n<body>\n<h1>" + html_escape(doc.title) + "</h1>\n";
  for (const auto& b : doc.blocks) h += html_block(b);
  return h + "</body>\n</html>\n";
}

}  // namespace spifit::reports
