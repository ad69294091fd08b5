// The output folder of a run (model-format.md "Results in DIR"): created when missing, never
// silently taken over from another model, cleaned of the previous results of the same model;
// and log.txt, which receives everything the run prints.
#pragma once

#include <fmt/format.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <mutex>
#include <string>
#include <string_view>
#include <utility>

namespace fpmshell {

class Progress;

/// Marker file in DIR holding the absolute path of the model whose results DIR holds.
inline constexpr const char* k_model_marker = ".fpmshell_model";
/// Result files a run writes in DIR (besides fields/frame_NNNNN.vtu and the marker), and the
/// plots tools/plot_history.py adds. Their presence means "DIR holds results"; a run of the
/// same model removes them first (so no plot of an older run is left beside new results).
inline constexpr std::array<const char*, 8> k_result_files = {
    "summary.json", "history.csv", "energy.csv", "fields.pvd",
    "log.txt",      "history.png", "energy.png", "restart.bin"};
/// Folder of the VTU frames, inside DIR.
inline constexpr const char* k_fields_folder = "fields";

/// The piece of a distributed run's restart file (restart.bin) that rank `rank` wrote after step
/// `step`: restart_rankR_stepN.bin in DIR.
[[nodiscard]] inline std::string restart_piece_file(int rank, long step) {
    return fmt::format("restart_rank{}_step{}.bin", rank, step);
}
/// Deletes DIR's restart pieces of every step but `keep_step` (those of an older restart file,
/// or of one whose writing was cut short) and their leftover temporary files.
void remove_restart_pieces_except(const std::filesystem::path& dir, long keep_step);

/// Makes `dir` ready for a run of `model_file`:
///  - creates it (and its parents) when missing, with a `fields/` folder inside;
///  - when it holds results (any of k_result_files, or frames in fields/) of another model, or
///    of a model it cannot tell (no marker), throws InputError unless `overwrite` is true;
///  - otherwise (same model, or `overwrite`) deletes those result files, the fields/frame_*.vtu
///    frames, the restart pieces of distributed runs and leftover temporary files, and nothing else
///    (DIR may be a folder the user keeps other files in);
///  - records the absolute path of `model_file` in DIR/.fpmshell_model.
/// Throws InputError (one sentence naming DIR) when DIR is a file or cannot be created or
/// cleaned.
void prepare_run_directory(const std::filesystem::path& dir,
                           const std::filesystem::path& model_file, bool overwrite);

/// Makes `dir` ready to resume the run of `model_file` it holds (fpmshell run --resume): DIR
/// must hold a restart file (restart.bin) of that model, as recorded by its marker, unless
/// `overwrite`. Nothing is removed here; the caller removes the frames written after the
/// restart file with remove_frames_from(). Throws InputError (one sentence naming DIR).
void prepare_resume_directory(const std::filesystem::path& dir,
                              const std::filesystem::path& model_file, bool overwrite);

/// Deletes DIR/fields/frame_NNNNN.vtu for every NNNNN >= first (frames a run wrote after its
/// last restart file, which the resumed run writes again) and leftover temporary files.
void remove_frames_from(const std::filesystem::path& dir, int first);

/// Text sink that echoes to stdout and appends to a log file (DIR/log.txt), flushing both on
/// every write, so the log is complete up to the last line even if the run is killed.
/// Thread-safe (one lock per write).
class LogFile {
public:
    /// Opens `path` for appending (prepare_run_directory removes the previous run's log, so a
    /// run starts with an empty one). `echo`: also print to stdout. Throws std::runtime_error
    /// when the file cannot be opened.
    explicit LogFile(const std::filesystem::path& path, bool echo = true);
    ~LogFile();
    LogFile(const LogFile&) = delete;
    LogFile& operator=(const LogFile&) = delete;

    /// Writes `text` as given.
    void write(std::string_view text);
    /// Writes `text` and a line break.
    void line(std::string_view text);
    /// fmt-formatted line: log.print("step {} dt {:.3e}", n, dt).
    template <class... Args>
    void print(fmt::format_string<Args...> format, Args&&... args) {
        line(fmt::format(format, std::forward<Args>(args)...));
    }

    /// A live progress line to erase before echoing to stdout (nullptr: none). Not owned.
    void set_progress(Progress* progress) { progress_ = progress; }

    [[nodiscard]] const std::filesystem::path& path() const { return path_; }

private:
    std::filesystem::path path_;
    std::FILE* file_ = nullptr;
    bool echo_;
    Progress* progress_ = nullptr;
    std::mutex mutex_;
};

}  // namespace fpmshell
