// Anchor translation unit of spifit_reports (the library's sources are globbed).
namespace spifit::reports {
const char* reports_library_name() { return "spifit_reports"; }
}  // namespace spifit::reports
