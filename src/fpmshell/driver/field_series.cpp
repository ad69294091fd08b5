// VTU frame series observer; described in field_series.hpp.
#include "fpmshell/driver/field_series.hpp"

#include <fmt/format.h>

#include <exception>

#include "fpmshell/io/restart_archive.hpp"
#include "fpmshell/io/run_directory.hpp"
#include "fpmshell/solver/explicit_solver.hpp"

namespace fpmshell {

FieldSeries::FieldSeries(const Model& model, std::filesystem::path dir,
                         std::vector<OutputField> fields, LogSink log)
    : model_(model), dir_(std::move(dir)), fields_(std::move(fields)), log_(std::move(log)) {}

void FieldSeries::load(RestartReader& restart) {
    restart.section("fields");
    restart(frames_);
    resumed_ = true;
}

void FieldSeries::start(const ExplicitSolver& /*solver*/) {
    if (resumed_) remove_frames_from(dir_, static_cast<int>(frames_.size()));
    pvd_.emplace(dir_ / "fields.pvd");
    for (const auto& [time, file] : frames_) pvd_->add(time, file);
}

void FieldSeries::frame(const ExplicitSolver& solver, Real time,
                        const std::vector<Vec3>& positions) {
    const std::string file = fmt::format("{}/frame_{:05d}.vtu", k_fields_folder, frames_.size());
    const OutputControl& output = model_.output;
    const VtuFormat format(output.fields_encoding == FieldsEncoding::Base64  ? VtuEncoding::Base64
                           : output.fields_encoding == FieldsEncoding::Ascii ? VtuEncoding::Ascii
                                                                             : VtuEncoding::Raw,
                           output.fields_zlib ? VtuCompression::Zlib : VtuCompression::None);
    field_frame(fields_, {model_, solver, positions}, time, frame_);
    write_vtu(dir_ / file, frame_, format);
    frames_.emplace_back(time, file);
    pvd_->add(time, file);
}

void FieldSeries::failure(const ExplicitSolver& solver, std::string_view /*error*/,
                          const std::vector<Vec3>& last_good_positions) {
    try {
        frame(solver, solver.time(), last_good_positions);
    } catch (const std::exception& e) {
        log_(fmt::format("could not write the last frame: {}", e.what()));
    }
}

void FieldSeries::save(RestartWriter& restart) const {
    restart.section("fields");
    restart(frames_);
}

}  // namespace fpmshell
