#pragma once
// The document model of the reports: a title and a sequence of blocks (headings, paragraphs,
// tables, callout boxes, lists, figures) holding plain text. Writers turn it into Markdown
// (markdown_writer.hpp) or HTML (html_writer.hpp) and do all the escaping; nothing in here
// knows what a report is about.
#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace spifit::reports {

// A run of text, optionally bold, code (monospace) or a link.
struct Span {
  std::string text;
  bool bold = false, code = false;
  std::string href;
  Span(std::string t) : text(std::move(t)) {}  // NOLINT: implicit, plain text
  Span(std::string t, bool b, bool c, std::string h = {}) : text(std::move(t)), bold(b), code(c), href(std::move(h)) {}
};
using Inline = std::vector<Span>;

// How a table cell is emphasised. Markdown: bad bold, warn italic; HTML: a CSS class.
enum class CellStyle { plain, good, warn, bad, diagonal };

struct Cell {
  std::string text;
  CellStyle style = CellStyle::plain;
  // A value in [-1, 1] shown as a background tint in HTML (blue positive, red negative) when
  // finite and the style is plain, e.g. a correlation.
  double shade = std::numeric_limits<double>::quiet_NaN();
};

inline Cell cell(std::string text, CellStyle style = CellStyle::plain) {
  Cell c;
  c.text = std::move(text);
  c.style = style;
  return c;
}

struct Table {
  std::string id;  // HTML id, for links and tests
  std::vector<std::string> header;
  std::vector<bool> right;  // right-aligned (numeric) columns
  std::vector<std::vector<Cell>> rows;
};

// A box of items under a title: warnings (red), notes (yellow), all clear (green).
enum class CalloutKind { warning, note, ok };

struct Block {
  enum class Kind { heading, paragraph, table, callout, list, figure };
  explicit Block(Kind k) : kind(k) {}
  Kind kind;
  int level = 2;       // heading
  std::string anchor;  // heading: HTML id
  Inline text;         // heading, paragraph
  Table table;
  CalloutKind callout = CalloutKind::note;
  std::string title;         // callout
  std::vector<Inline> items;  // callout, list
  std::string src, alt;       // figure: image path relative to the document, caption
};

struct Document {
  std::string title;
  std::vector<Block> blocks;

  void heading(int level, const std::string& text, const std::string& anchor = "") {
    Block b{Block::Kind::heading};
    b.level = level;
    b.text = {{text}};
    b.anchor = anchor;
    blocks.push_back(std::move(b));
  }
  void para(Inline text) {
    Block b{Block::Kind::paragraph};
    b.text = std::move(text);
    blocks.push_back(std::move(b));
  }
  void table(Table t) {
    Block b{Block::Kind::table};
    b.table = std::move(t);
    blocks.push_back(std::move(b));
  }
  void callout(CalloutKind kind, const std::string& box_title, std::vector<Inline> items) {
    Block b{Block::Kind::callout};
    b.callout = kind;
    b.title = box_title;
    b.items = std::move(items);
    blocks.push_back(std::move(b));
  }
  void list(std::vector<Inline> items) {
    Block b{Block::Kind::list};
    b.items = std::move(items);
    blocks.push_back(std::move(b));
  }
  void figure(const std::string& src, const std::string& alt) {
    Block b{Block::Kind::figure};
    b.src = src;
    b.alt = alt;
    blocks.push_back(std::move(b));
  }
};

}  // namespace spifit::reports
