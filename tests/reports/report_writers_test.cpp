// The report document model and its writers on a small document that is not a fit report:
// every block kind in Markdown and HTML, escaping of hostile text, cell styles and shades.
#include "reports/html_writer.hpp"
#include "reports/markdown_writer.hpp"
#include "reports/report_document.hpp"
#include "reports/report_format.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace spifit::reports;

namespace {

Document sample() {
  Document d;
  d.title = "Run <1> | a*b";
  d.heading(2, "Section", "sec");
  d.para({{"plain "}, {"bold", true, false}, {" and "}, {"code`x", false, true}, {" "}, {"link", false, false, "a.html"}});
  d.callout(CalloutKind::warning, "Two problems", {{{"first"}}, {{"second <b>"}}});
  d.list({{{"one"}}, {{"two"}}});
  Table t;
  t.id = "numbers";
  t.header = {"name", "value"};
  t.right = {false, true};
  Cell shaded = cell("0.5");
  shaded.shade = -0.5;
  t.rows = {{cell("a|b"), cell("1", CellStyle::bad)}, {cell("c"), cell("2", CellStyle::warn)}, {cell("d", CellStyle::diagonal), shaded}};
  d.table(t);
  d.figure("plots/x.svg", "caption \"quoted\"");
  return d;
}

TEST(MarkdownWriter, WritesEveryBlockKind) {
  const std::string md = to_markdown(sample());
  EXPECT_EQ(md.rfind("# Run <1> \\| a\\*b\n", 0), 0u) << md;
  EXPECT_NE(md.find("\n## Section\n"), std::string::npos);
  EXPECT_NE(md.find("plain **bold** and `code'x` [link](a.html)\n"), std::string::npos) << md;
  EXPECT_NE(md.find("> **Two problems**\n>\n> - first\n> - second &lt;b>\n"), std::string::npos) << md;
  EXPECT_NE(md.find("\n- one\n- two\n"), std::string::npos);
  EXPECT_NE(md.find("| name | value |\n|---|---:|\n| a\\|b | **1** |\n| c | *2* |\n| d | 0.5 |\n"), std::string::npos) << md;
  EXPECT_NE(md.find("![caption \"quoted\"](plots/x.svg)\n"), std::string::npos);
}

TEST(HtmlWriter, EscapesTextAndStylesCells) {
  const std::string html = to_html(sample());
  EXPECT_EQ(html.rfind("<!DOCTYPE html>\n", 0), 0u);
  EXPECT_NE(html.find("<title>Run &lt;1&gt; | a*b</title>"), std::string::npos);
  EXPECT_NE(html.find("<h2 id=\"sec\">Section</h2>"), std::string::npos);
  EXPECT_NE(html.find("<strong>bold</strong>"), std::string::npos);
  EXPECT_NE(html.find("<a href=\"a.html\">link</a>"), std::string::npos);
  EXPECT_NE(html.find("<div class=\"callout warn\">\n<p>Two problems</p>\n<ul>\n<li>first</li>\n<li>second &lt;b&gt;</li>"), std::string::npos);
  EXPECT_NE(html.find("<table id=\"numbers\">"), std::string::npos);
  EXPECT_NE(html.find("<td>a|b</td><td class=\"num bad\">1</td>"), std::string::npos) << html;
  EXPECT_NE(html.find("<td class=\"num warn\">2</td>"), std::string::npos);
  EXPECT_NE(html.find("<td class=\"diag\">d</td><td class=\"num\" style=\"background:rgba(214,39,40,0.38)\">0.5</td>"), std::string::npos)
      << html;
  EXPECT_NE(html.find("<img src=\"plots/x.svg\" alt=\"caption &quot;quoted&quot;\">"), std::string::npos);
  EXPECT_EQ(html.find("<b>"), std::string::npos);
  EXPECT_EQ(html.substr(html.size() - 16), "</body>\n</html>\n");
}

TEST(ReportFormat, NumbersAndLabels) {
  EXPECT_EQ(format_significant(1234.5678), "1234.57");
  EXPECT_EQ(format_significant(1234.5678, 3), "1.23e+03");
  EXPECT_EQ(format_significant(NAN), "n/a");
  EXPECT_EQ(format_fixed(-0.0001, 3), "0.000");
  EXPECT_EQ(format_fixed(-0.5, 1), "-0.5");
  EXPECT_EQ(format_percent(0.1234), "12.3 %");
  EXPECT_EQ(format_percent(0.0001), "< 0.1 %");
  EXPECT_EQ(with_unit("3", "MPa"), "3 MPa");
  EXPECT_EQ(with_unit("3", "-"), "3");
  EXPECT_EQ(axis_label("", "mm", "x"), "x [mm]");
  EXPECT_EQ(axis_label("strain", "-", "x"), "strain");
}

}  // namespace
