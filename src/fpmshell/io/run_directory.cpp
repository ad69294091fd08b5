// Output folder preparation and the log tee; behaviour described in run_directory.hpp.
#include "fpmshell/io/run_directory.hpp"

#include <cerrno>
#include <cstring>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <system_error>

#include "fpmshell/core/errors.hpp"
#include "fpmshell/io/atomic_file.hpp"
#include "fpmshell/io/progress.hpp"

namespace fpmshell {

namespace fs = std::filesystem;

namespace {

[[noreturn]] void dir_error(const fs::path& dir, const std::string& message) {
    throw InputError(input_error_text(dir.string(), 0, "", message));
}

/// Absolute, normalised path (symbolic links resolved where the path exists).
fs::path absolute_model_path(const fs::path& model_file) {
    std::error_code ec;
    fs::path p = fs::weakly_canonical(fs::absolute(model_file), ec);
    if (ec) p = fs::absolute(model_file).lexically_normal();
    return p;
}

/// The model recorded in DIR's marker, or "" when there is none.
std::string recorded_model(const fs::path& dir) {
    std::ifstream in(dir / k_model_marker);
    if (!in) return {};
    std::stringstream ss;
    ss << in.rdbuf();
    std::string text = ss.str();
    while (!text.empty() && (text.back() == '\n' || text.back() == '\r' || text.back() == ' ')) {
        text.pop_back();
    }
    return text;
}

bool starts_with(const std::string& s, std::string_view prefix) {
    return s.size() >= prefix.size() && s.compare(0, prefix.size(), prefix) == 0;
}

/// The step of a restart piece "restart_rankR_stepN.bin" (or of its temporary file), -1 for a
/// name of another file.
long restart_piece_step(const std::string& name) {
    if (!starts_with(name, "restart_rank")) return -1;
    const std::size_t at = name.find("_step");
    const std::size_t end = name.find(".bin");
    if (at == std::string::npos || end == std::string::npos || end <= at + 5) return -1;
    try {
        std::size_t used = 0;
        const long step = std::stol(name.substr(at + 5, end - at - 5), &used);
        return used == end - at - 5 && step >= 0 ? step : -1;
    } catch (const std::exception&) {
        return -1;
    }
}

/// True for a VTU frame written by the run ("frame_*.vtu"; on several ranks "frame_*.pvtu" and
/// its pieces "frame_*_rank*.vtu") or one's leftover temporary file.
bool is_frame_file(const std::string& name) {
    return starts_with(name, "frame_") && (name.ends_with(".vtu") || name.ends_with(".pvtu") ||
                                           name.find("vtu.tmp.") != std::string::npos);
}

bool holds_frames(const fs::path& fields) {
    std::error_code ec;
    if (!fs::is_directory(fields, ec)) return false;
    for (const auto& entry : fs::directory_iterator(fields, ec)) {
        if (is_frame_file(entry.path().filename().string())) return true;
    }
    return false;
}

bool holds_results(const fs::path& dir) {
    std::error_code ec;
    for (const char* name : k_result_files) {
        if (fs::exists(dir / name, ec)) return true;
    }
    return holds_frames(dir / k_fields_folder);
}

void remove_file(const fs::path& dir, const fs::path& file) {
    std::error_code ec;
    fs::remove(file, ec);
    if (ec) {
        dir_error(dir, "cannot remove the old result '" + file.filename().string() + "' (" +
                           ec.message() + "); check the folder's permissions.");
    }
}

/// Deletes our files in DIR (not in its fields folder): the temporaries of our named files (left
/// by a process killed while it wrote one, write_file_atomic), and with `results` the named
/// files themselves. Nothing else is touched.
void remove_our_files(const fs::path& dir, bool results) {
    std::error_code ec;
    for (const auto& entry : fs::directory_iterator(dir, ec)) {
        const std::string name = entry.path().filename().string();
        bool ours = false;
        for (const char* result : k_result_files) {
            if ((results && name == result) || starts_with(name, std::string(result) + ".tmp."))
                ours = true;
        }
        if (starts_with(name, std::string(k_model_marker) + ".tmp.")) ours = true;
        const long piece_step = restart_piece_step(name);
        if (piece_step >= 0 && (results || name.find(".bin.tmp.") != std::string::npos))
            ours = true;
        if (ours && !entry.is_directory(ec)) remove_file(dir, entry.path());
    }
}

/// Deletes the previous results of a run in DIR: our named files, their temporaries and the
/// VTU frames. Nothing else is touched.
void clean_results(const fs::path& dir) {
    std::error_code ec;
    remove_our_files(dir, true);
    const fs::path fields = dir / k_fields_folder;
    if (fs::is_directory(fields, ec)) {
        for (const auto& entry : fs::directory_iterator(fields, ec)) {
            if (is_frame_file(entry.path().filename().string()) && !entry.is_directory(ec)) {
                remove_file(dir, entry.path());
            }
        }
    }
}

}  // namespace

void prepare_run_directory(const fs::path& dir, const fs::path& model_file, bool overwrite) {
    const std::string model = absolute_model_path(model_file).string();
    std::error_code ec;
    if (fs::exists(dir, ec) && !fs::is_directory(dir, ec)) {
        dir_error(dir, "the output directory is an existing file; choose another path with -o.");
    }
    if (!fs::exists(dir, ec)) {
        fs::create_directories(dir, ec);
        if (ec) {
            dir_error(dir, "cannot create the output directory (" + ec.message() +
                               "); choose another path with -o.");
        }
    } else if (holds_results(dir)) {
        const std::string recorded = recorded_model(dir);
        if (recorded != model && !overwrite) {
            const std::string other =
                recorded.empty() ? "a model it cannot identify" : "'" + recorded + "'";
            dir_error(dir, "the output directory holds results of " + other +
                               "; use --overwrite to replace them or choose another directory "
                               "with -o.");
        }
    }
    clean_results(dir);

    const fs::path fields = dir / k_fields_folder;
    if (fs::exists(fields, ec) && !fs::is_directory(fields, ec)) {
        dir_error(dir, "'" + fields.string() +
                           "' is a file, but the VTU frames go into a folder "
                           "of that name; remove it or choose another directory with -o.");
    }
    fs::create_directories(fields, ec);
    if (ec) {
        dir_error(dir,
                  "cannot create the folder '" + fields.string() + "' (" + ec.message() + ").");
    }
    try {
        write_file_atomic(dir / k_model_marker, model + "\n");
    } catch (const std::runtime_error& e) {
        dir_error(dir, std::string("cannot record the model in the output directory: ") + e.what());
    }
}

void prepare_resume_directory(const fs::path& dir, const fs::path& model_file, bool overwrite) {
    const std::string model = absolute_model_path(model_file).string();
    std::error_code ec;
    if (!fs::is_directory(dir, ec))
        dir_error(dir, "there is no result folder to resume a run from; give it with -o.");
    if (!fs::exists(dir / "restart.bin", ec))
        dir_error(dir,
                  "the folder holds no restart file (restart.bin) to resume from; the run must be "
                  "started "
                  "with --restart-every.");
    const std::string recorded = recorded_model(dir);
    if (recorded != model && !overwrite) {
        const std::string other =
            recorded.empty() ? "a model it cannot identify" : "'" + recorded + "'";
        dir_error(dir, "the restart file belongs to " + other +
                           "; use --overwrite to resume it with this model file.");
    }
    remove_our_files(dir, false);  // the frames' temporaries go with the frames after the restart
    fs::create_directories(dir / k_fields_folder, ec);
    if (ec)
        dir_error(dir, "cannot create the folder '" + (dir / k_fields_folder).string() + "' (" +
                           ec.message() + ").");
}

void remove_restart_pieces_except(const fs::path& dir, long keep_step) {
    std::error_code ec;
    for (const auto& entry : fs::directory_iterator(dir, ec)) {
        const std::string name = entry.path().filename().string();
        const long step = restart_piece_step(name);
        const bool temporary = name.find(".bin.tmp.") != std::string::npos;
        if (step >= 0 && (step != keep_step || temporary) && !entry.is_directory(ec))
            remove_file(dir, entry.path());
    }
}

void remove_frames_from(const fs::path& dir, int first) {
    std::error_code ec;
    for (const auto& entry : fs::directory_iterator(dir / k_fields_folder, ec)) {
        const std::string name = entry.path().filename().string();
        if (!is_frame_file(name) || entry.is_directory(ec)) continue;
        // frame_NNNNN.vtu (.pvtu, _rankR.vtu): the number follows "frame_"; a temporary file is
        // always stale.
        const bool temporary = name.find("vtu.tmp.") != std::string::npos;
        int index = -1;
        try {
            index = std::stoi(name.substr(6));
        } catch (const std::exception&) {
            continue;  // not one of ours
        }
        if (temporary || index >= first) remove_file(dir, entry.path());
    }
}

LogFile::LogFile(const fs::path& path, bool echo) : path_(path), echo_(echo) {
    file_ = std::fopen(path_.c_str(), "a");
    if (file_ == nullptr) {
        throw std::runtime_error("cannot open the log file '" + path_.string() + "' (" +
                                 std::strerror(errno) + ").");
    }
}

LogFile::~LogFile() {
    if (file_ != nullptr) std::fclose(file_);
}

void LogFile::write(std::string_view text) {
    std::lock_guard<std::mutex> lock(mutex_);
    if (echo_) {
        if (progress_ != nullptr) progress_->clear_line();
        std::fwrite(text.data(), 1, text.size(), stdout);
        std::fflush(stdout);
    }
    // A failed log write must not stop the run; the text still reached stdout.
    std::fwrite(text.data(), 1, text.size(), file_);
    std::fflush(file_);
}

void LogFile::line(std::string_view text) {
    std::string s(text);
    s += '\n';
    write(s);
}

}  // namespace fpmshell
