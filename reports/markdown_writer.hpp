#pragma once
// A Document (report_document.hpp) as GitHub Markdown: "# title", tables with alignment rows,
// callouts as block quotes, figures as images.
#include "reports/report_document.hpp"

#include <string>

namespace spifit::reports {

// Text that Markdown shows literally: \ | * ` escaped, "](" and HTML-like "<x" defused,
// line breaks and tabs as spaces.
std::string markdown_escape(const std::string& text);

std::string to_markdown(const Document& doc);

}  // namespace spifit::reports
