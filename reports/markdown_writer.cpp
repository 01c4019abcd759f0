#include "reports/markdown_writer.hpp"

#include <cctype>

namespace spifit::reports {

std::string markdown_escape(const std::string& s) {
  std::string out;
  for (std::size_t i = 0; i < s.size(); ++i) {
    const char c = s[i];
    const char next = i + 1 < s.size() ? s[i + 1] : '\0';
    switch (c) {
      case '\\': out += "\\\\"; break;
      case '|': out += "\\|"; break;
      case '*': out += "\\*"; break;
      case '`': out += "\\`"; break;
      case ']': out += next == '(' ? "\\]" : "]"; break;  // "[a](b)" would become a link
      case '<': out += (std::isalpha(static_cast<unsigned char>(next)) || next == '/' || next == '!' || next == '?') ? "&lt;" : "<"; break;
      case '\n': case '\r': case '\t': out += ' '; break;
      default: out += c;
    }
  }
  return out;
}

namespace {

std::string md_inline(const Inline& spans) {
  std::string out;
  for (const auto& s : spans) {
    std::string t;
    if (s.code) {
      std::string c = s.text;
      for (auto& ch : c) {
        if (ch == '`' || ch == '\n' || ch == '\r') ch = '\'';
      }
      t = "`" + c + "`";
    } else {
      t = markdown_escape(s.text);
    }
    if (!s.href.empty()) t = "[" + t + "](" + s.href + ")";
    if (s.bold) t = "**" + t + "**";
    out += t;
  }
  return out;
}

std::string md_table(const Table& t) {
  std::string md = "|";
  for (const auto& h : t.header) {
    md += ' ';
    md += markdown_escape(h);
    md += " |";
  }
  md += "\n|";
  for (std::size_t k = 0; k < t.header.size(); ++k) md += (k < t.right.size() && t.right[k]) ? "---:|" : "---|";
  md += "\n";
  for (const auto& row : t.rows) {
    md += "|";
    for (const auto& c : row) {
      const std::string text = markdown_escape(c.text);
      std::string shown = text;
      if (!text.empty() && c.style == CellStyle::bad) shown = "**" + text + "**";
      if (!text.empty() && c.style == CellStyle::warn) shown = "*" + text + "*";
      md += ' ';
      md += shown;
      md += " |";
    }
    md += "\n";
  }
  return md;
}

std::string md_block(const Block& b) {
  switch (b.kind) {
    case Block::Kind::heading: return std::string(static_cast<std::size_t>(b.level), '#') + " " + md_inline(b.text) + "\n";
    case Block::Kind::paragraph: return md_inline(b.text) + "\n";
    case Block::Kind::callout: {
      std::string md = "> **" + markdown_escape(b.title) + "**\n>\n";
      for (const auto& it : b.items) md += "> - " + md_inline(it) + "\n";
      return md;
    }
    case Block::Kind::list: {
      std::string md;
      for (const auto& it : b.items) md += "- " + md_inline(it) + "\n";
      return md;
    }
    case Block::Kind::figure: return "![" + markdown_escape(b.alt) + "](" + b.src + ")\n";
    case Block::Kind::table: return md_table(b.table);
  }
  return {};
}

}  // namespace

std::string to_markdown(const Document& doc) {
  std::string md = "# " + markdown_escape(doc.title) + "\n";
  for (const auto& b : doc.blocks) {
    md += '\n';
    md += md_block(b);
  }
  return md;
}

}  // namespace spifit::reports
