// A validation report folder (`shadowvol validate --report DIR`, Python validate(report_dir=DIR)):
// which files are the report's, how an earlier report is cleared, and where each light's images go.
// Both writers follow one rule, so a folder never holds one run's report beside another's images.
#pragma once

#include <filesystem>
#include <string>
#include <span>

#include <nlohmann/json.hpp>

namespace shadowvol {

/// The files a report writes in its folder (and in each light-K folder of several lights), the
/// report first: removeReportFiles takes it before the images it describes.
std::span<const char* const> reportFileNames();

/// Removes what an earlier report (or this one, failing) wrote in `dir`: the files of
/// reportFileNames there and in its light-K folders, and a light-K folder left empty. Nothing else
/// is touched: a light-K that is a symbolic link is not followed (a fourteenth probe's link to
/// another folder had its files deleted), and a report file that is a link is removed, not its
/// target. Call it under an OutputLock on `dir`.
void removeReportFiles(const std::filesystem::path& dir);

/// Writes `report` as dir/report.json (atomically: whole or not at all), the last file of a report.
void writeReportJson(const std::filesystem::path& dir, const nlohmann::json& report);

/// The name of light k's image folder in a report folder: "light-k" (report.json's imageFolder).
std::string lightReportFolderName(std::size_t k);

/// Light k's image folder in `dir` (dir / lightReportFolderName(k)), refused (InputError) when it is a symbolic link:
/// the images would go where it points.
std::filesystem::path lightReportFolder(const std::filesystem::path& dir, std::size_t k);

}  // namespace shadowvol
