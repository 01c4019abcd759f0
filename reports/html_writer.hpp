#pragma once
// A Document (report_document.hpp) as one self-contained HTML page: inline CSS, no scripts,
// images referenced by their relative paths. All text is escaped.
#include "reports/report_document.hpp"

#include <string>

namespace spifit::reports {

// & < > " ' as character references.
std::string html_escape(const std::string& text);

std::string to_html(const Document& doc);

}  // namespace spifit::reports
