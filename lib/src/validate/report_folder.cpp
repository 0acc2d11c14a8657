#include "shadowvol/report_json.h"
#include "shadowvol/validate/report_folder.h"

#include <fstream>
#include <string>

#include "shadowvol/error.h"
#include "shadowvol/mesh_io.h"  // writeAtomically

namespace shadowvol {
namespace {

constexpr const char* kReportFiles[] = {"report.json", "frame.png",   "exact.png",  "stencil.png",
                                        "count.png",   "overlay.png", "overlay.svg"};

}  // namespace

std::span<const char* const> reportFileNames() { return kReportFiles; }

void removeReportFiles(const std::filesystem::path& dir) {
  std::error_code ec;
  auto removeIn = [&](const std::filesystem::path& d) {
    for (const char* name : kReportFiles) std::filesystem::remove(d / name, ec);  // a link itself, not its target
  };
  removeIn(dir);
  for (const auto& e : std::filesystem::directory_iterator(dir, ec)) {
    const std::string name = e.path().filename().string();
    if (e.is_symlink(ec) || !e.is_directory(ec) || name.rfind("light-", 0) != 0 || name.size() == 6 ||
        name.find_first_not_of("0123456789", 6) != std::string::npos)
      continue;
    removeIn(e.path());
    if (std::filesystem::is_empty(e.path(), ec)) std::filesystem::remove(e.path(), ec);
  }
}

void writeReportJson(const std::filesystem::path& dir, const nlohmann::json& report) {
  const std::filesystem::path path = dir / "report.json";
  writeAtomically(path, [&](const std::filesystem::path& tmp) {
    std::ofstream out(tmp);
    out << jsonText(report) << '\n';
    out.flush();
    if (!out) throw InputError(path.string(), "", "", "writing the report failed");
  });
}

std::string lightReportFolderName(std::size_t k) { return "light-" + std::to_string(k); }

std::filesystem::path lightReportFolder(const std::filesystem::path& dir, std::size_t k) {
  const std::filesystem::path sub = dir / lightReportFolderName(k);
  std::error_code ec;
  if (std::filesystem::is_symlink(sub, ec))
    throw InputError(sub.string(), "", "", "is a symbolic link: validate writes each light's images in a "
                                           "folder of its own inside the report folder; remove the link");
  return sub;
}

}  // namespace shadowvol
