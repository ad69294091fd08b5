// Crash-safe file replacement (model-format.md "Results in DIR"): a run killed at any moment
// leaves every result file readable, holding either its previous or its new content.
#pragma once

#include <filesystem>
#include <span>
#include <string_view>

namespace fpmshell {

/// Replaces the file at `path` with `content` (bytes, written as given).
/// The content goes to `<path>.tmp.<pid>` in the same folder first and is then renamed over
/// `path` (an atomic replacement on POSIX file systems), so readers and a later crash never see
/// a half-written file. The folder must exist. Throws std::runtime_error with one sentence
/// naming the file and the system's reason on failure; the temporary file is removed then.
void write_file_atomic(const std::filesystem::path& path, std::string_view content);

/// The same with the content given as pieces written one after the other (a file assembled from
/// buffers that lie elsewhere, without copying them into one).
void write_file_atomic(const std::filesystem::path& path, std::span<const std::string_view> pieces);

/// Name of the temporary file write_file_atomic uses for `path` in this process.
[[nodiscard]] std::filesystem::path atomic_temp_path(const std::filesystem::path& path);

}  // namespace fpmshell
