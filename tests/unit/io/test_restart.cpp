// Restart files (io/restart_archive.hpp, fpmshell run --restart-every / --resume):
// - the archive reads back every kind of value bit for bit, and refuses a truncated, foreign
//   or reordered file with an InputError naming it;
// - a run stopped part way and resumed writes the same bytes as the run that never stopped,
//   on the square tube (plasticity, self-contact, a rigid body, variable step);
// - so does a run whose mass scaling adds mass during the run;
// - a restart file does not resume another model;
// - a file of an earlier or a later format is refused with one sentence that says what to do;
// - (the same byte comparison, for threads) the tube writes the same results on 1 and 2
//   threads: elements, particles, rigid body and contact.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <utility>

#include "../eroding_band.hpp"
#include "../lap_joint.hpp"
#include "fpmshell/core/errors.hpp"
#include "fpmshell/driver/run_driver.hpp"
#include "fpmshell/failure/tabulated/tabulated_failure.hpp"
#include "fpmshell/io/model_reader.hpp"
#include "fpmshell/io/restart_archive.hpp"
#include "fpmshell/materials/material_point.hpp"
#include "fpmshell/solver/explicit_solver.hpp"

namespace fpmshell {
namespace {

namespace fs = std::filesystem;

fs::path fresh_dir(const std::string& name) {
    const fs::path p =
        fs::temp_directory_path() / ("fpmshell_restart_" + name + "_" + std::to_string(::getpid()));
    fs::remove_all(p);
    fs::create_directories(p);
    return p;
}

std::string bytes_of(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

TEST(RestartArchive, ReadsBackEveryKindOfValueBitForBit) {
    const fs::path dir = fresh_dir("archive");
    MaterialPoint mp;
    mp.stress = Voigt3(1.0 / 3.0, -2e-300, 7.5);
    mp.back_stress = Voigt3(0.1, 0.2, 0.3);
    mp.plastic_strain = 0.123456789012345678;
    mp.flow_radius = 350e6;
    const std::vector<Vec3> vectors{Vec3(1, 2, 3), Vec3(-0.0, 1e-310, 4)};
    const std::vector<std::vector<Real>> rows{{1, 2}, {}, {3}};
    const std::vector<std::pair<Real, std::string>> frames{{0.5, "fields/frame_00001.vtu"}};
    const Mat3 rotation = Eigen::AngleAxisd(0.7, Vec3(1, 1, 0).normalized()).toRotationMatrix();
    {
        RestartWriter w;
        w.section("one");
        w(mp, vectors, rows, frames, rotation, 42L, true);
        w.save(dir / "r.bin");
    }
    MaterialPoint mp2;
    std::vector<Vec3> vectors2;
    std::vector<std::vector<Real>> rows2;
    std::vector<std::pair<Real, std::string>> frames2;
    Mat3 rotation2;
    long n = 0;
    bool flag = false;
    RestartReader r(dir / "r.bin");
    r.section("one");
    r(mp2, vectors2, rows2, frames2, rotation2, n, flag);
    r.finish();
    EXPECT_EQ(mp2.stress, mp.stress);  // exact: the bytes are copied
    EXPECT_EQ(mp2.back_stress, mp.back_stress);
    EXPECT_EQ(mp2.plastic_strain, mp.plastic_strain);
    EXPECT_EQ(mp2.flow_radius, mp.flow_radius);
    EXPECT_EQ(vectors2, vectors);
    EXPECT_TRUE(std::signbit(vectors2[1].x()));
    EXPECT_EQ(rows2, rows);
    EXPECT_EQ(frames2, frames);
    EXPECT_EQ(rotation2, rotation);
    EXPECT_EQ(n, 42);
    EXPECT_TRUE(flag);
    fs::remove_all(dir);
}

TEST(RestartArchive, RefusesTruncatedForeignAndReorderedFiles) {
    const fs::path dir = fresh_dir("bad");
    {
        RestartWriter w;
        w.section("solver");
        w(std::vector<Real>(100, 1.0));
        w.save(dir / "good.bin");
    }
    const std::string good = bytes_of(dir / "good.bin");
    const std::string content = good.substr(0, good.size() - 4);  // without the CRC-32
    std::ofstream(dir / "short.bin", std::ios::binary) << good.substr(0, good.size() - 8);
    std::string flipped = good;
    flipped[flipped.size() / 2] ^= 0x10;  // one bit of one of the numbers
    std::ofstream(dir / "flipped.bin", std::ios::binary) << flipped;
    // content cut short or with a damaged length, behind a checksum that matches it
    std::ofstream(dir / "cut.bin", std::ios::binary)
        << RestartWriter::with_checksum(content.substr(0, content.size() - 8));
    std::string long_vector = content;
    const std::size_t length_at = content.size() - 100 * sizeof(Real) - sizeof(std::uint64_t);
    for (std::size_t i = 0; i < sizeof(std::uint64_t); ++i) long_vector[length_at + i] = '\xff';
    std::ofstream(dir / "long.bin", std::ios::binary) << RestartWriter::with_checksum(long_vector);
    std::ofstream(dir / "text.bin", std::ios::binary) << "title: not a restart file\n";
    auto message = [](auto&& f) {
        try {
            f();
        } catch (const InputError& e) {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    const std::string truncated = message([&] {
        RestartReader r(dir / "short.bin");
        r.section("solver");
        std::vector<Real> v;
        r(v);
    });
    EXPECT_NE(truncated.find("short.bin"), std::string::npos) << truncated;
    EXPECT_NE(truncated.find("damaged"), std::string::npos) << truncated;
    const std::string bit = message([&] { RestartReader r(dir / "flipped.bin"); });
    EXPECT_NE(bit.find("checksum does not match"), std::string::npos) << bit;
    auto read_vector = [&](const char* name) {
        return message([&] {
            RestartReader r(dir / name);
            r.section("solver");
            std::vector<Real> v;
            r(v);
        });
    };
    const std::string cut = read_vector("cut.bin");
    EXPECT_NE(cut.find("truncated"), std::string::npos) << cut;
    // 2^64 - 1 items: refused from the bytes left, before anything is allocated
    const std::string huge = read_vector("long.bin");
    EXPECT_NE(huge.find("truncated or corrupt (in section 'solver')"), std::string::npos) << huge;
    const std::string foreign = message([&] { RestartReader r(dir / "text.bin"); });
    EXPECT_NE(foreign.find("not an fpmshell restart file"), std::string::npos) << foreign;
    const std::string reordered = message([&] {
        RestartReader r(dir / "good.bin");
        r.section("elements");
    });
    EXPECT_NE(reordered.find("expected section 'elements', found 'solver'"), std::string::npos)
        << reordered;
    const std::string missing = message([&] { RestartReader r(dir / "none.bin"); });
    EXPECT_NE(missing.find("none.bin"), std::string::npos) << missing;
    fs::remove_all(dir);
}

/// The square tube example on a coarse mesh for `end` seconds: plasticity, self-contact and the
/// striker from the first steps (the block touches the tube at t = 0).
Model small_tube(Real end, int divisions_width = 6) {
    const std::string model = std::string(FPMSHELL_SOURCE_DIR) + "/examples/square_tube/model.yaml";
    return read_model(model, {"mesh.divisions_width=" + std::to_string(divisions_width),
                              "mesh.divisions_length=24", "control.end_time=" + std::to_string(end),
                              "output.fields_every=1e-4"});
}

/// Runs the model straight through into one fresh folder (straight) and stopped at step 217,
/// mid-way between two frames and two history rows, into another (first).
void run_straight_and_stopped(const Model& model, const std::string& tag, RunOptions& straight,
                              RunOptions& first) {
    straight = RunOptions{};
    straight.output_dir = fresh_dir("straight" + tag);
    straight.echo = false;
    straight.quiet = true;
    ASSERT_EQ(run_model(model, straight), 0);
    first = straight;
    first.output_dir = fresh_dir("pieces" + tag);
    first.stop_at_step = 217;
    ASSERT_EQ(run_model(model, first), 0);
}

/// Resumes the run stopped into first.output_dir to its end, and checks that its result files
/// hold the same bytes as those of the run that never stopped.
void resume_and_compare(const Model& model, const RunOptions& first, const RunOptions& straight) {
    RunOptions second = first;
    second.stop_at_step = 0;
    second.resume = true;
    ASSERT_EQ(run_model(model, second), 0);
    for (const char* file : {"history.csv", "energy.csv", "fields.pvd"})
        EXPECT_EQ(bytes_of(first.output_dir / file), bytes_of(straight.output_dir / file)) << file;
}

TEST(Restart, AStoppedAndResumedRunWritesTheSameBytesAsAnUninterruptedOne) {
    const Model model = small_tube(4e-4);
    RunOptions straight, first;
    ASSERT_NO_FATAL_FAILURE(run_straight_and_stopped(model, "", straight, first));
    ASSERT_TRUE(fs::exists(first.output_dir / k_restart_file));
    EXPECT_NE(bytes_of(first.output_dir / "history.csv"),
              bytes_of(straight.output_dir / "history.csv"));
    ASSERT_NO_FATAL_FAILURE(resume_and_compare(model, first, straight));
    int frames = 0;
    for (const auto& entry : fs::directory_iterator(straight.output_dir / "fields")) {
        const fs::path name = entry.path().filename();
        EXPECT_EQ(bytes_of(first.output_dir / "fields" / name), bytes_of(entry.path())) << name;
        ++frames;
    }
    EXPECT_GE(frames, 4);
    fs::remove_all(straight.output_dir);
    fs::remove_all(first.output_dir);
}

TEST(Restart, ABlastResumesBitForBit) {
    // the dome of examples/blast_dome stopped at step 217 (t = 0.21 ms), while the shock
    // passes over it (theory.md §6.13): the faces' pulses are set again from the model, their
    // angles from the resumed state
    const std::string path = std::string(FPMSHELL_SOURCE_DIR) + "/examples/blast_dome/model.yaml";
    const Model model = read_model(path, {"control.end_time=3e-4", "output.fields_every=1e-4"});
    RunOptions straight, first;
    ASSERT_NO_FATAL_FAILURE(run_straight_and_stopped(model, "_blast", straight, first));
    EXPECT_NE(bytes_of(first.output_dir / "history.csv"),
              bytes_of(straight.output_dir / "history.csv"));
    ASSERT_NO_FATAL_FAILURE(resume_and_compare(model, first, straight));
    fs::remove_all(straight.output_dir);
    fs::remove_all(first.output_dir);
}

/// The last field of the last line of a CSV text, and of its first data line.
std::pair<std::string, std::string> last_column_first_and_last(const std::string& csv) {
    std::istringstream in(csv);
    std::string line, first, last;
    std::getline(in, line);  // the header
    while (std::getline(in, line))
        if (!line.empty()) (first.empty() ? first : last) = line.substr(line.rfind(',') + 1);
    return {first, last};
}

TEST(Restart, MassScalingDuringTheRunResumesBitForBit) {
    // The tube's elements that are crushed fall below the target and gain mass during the run
    // (§6.10): the restart file carries the masses reached, and the contact's inverse masses
    // follow them.
    Model model = small_tube(4e-4);
    model.control.mass_scaling.time_step = 1.3 * ExplicitSolver(model).stable_dt();
    RunOptions straight, first;
    ASSERT_NO_FATAL_FAILURE(run_straight_and_stopped(model, "_ms", straight, first));
    // energy.csv's last column is the added mass: at the start, at the stop and at the end
    const std::string at_stop =
        last_column_first_and_last(bytes_of(first.output_dir / "energy.csv")).second;
    ASSERT_NO_FATAL_FAILURE(resume_and_compare(model, first, straight));
    const auto [at_start, at_end] =
        last_column_first_and_last(bytes_of(straight.output_dir / "energy.csv"));
    // mass was added before the stop and after it: the resumed part started from added masses
    // and added more
    EXPECT_LT(std::stod(at_start), std::stod(at_stop));
    EXPECT_LT(std::stod(at_stop), std::stod(at_end));
    fs::remove_all(straight.output_dir);
    fs::remove_all(first.output_dir);
}

TEST(Restart, AFileOfAnEarlierFormatIsRefusedWithOneSentence) {
    // A file of an earlier format holds the sections of an earlier layout (format 3: one
    // "results" section for every result file): the run must start again, and the message says so.
    const Model model = small_tube(4e-4);
    RunOptions first;
    first.output_dir = fresh_dir("earlier");
    first.echo = false;
    first.quiet = true;
    first.stop_at_step = 20;
    ASSERT_EQ(run_model(model, first), 0);
    const fs::path file = first.output_dir / k_restart_file;
    std::string bytes = bytes_of(file);
    std::uint32_t written = 0;
    std::memcpy(&written, bytes.data() + 8, sizeof(written));  // after the magic word
    RunOptions second = first;
    second.stop_at_step = 0;
    second.resume = true;
    for (const std::uint32_t version : {written - 1, written + 1}) {
        bytes.replace(8, sizeof(version), reinterpret_cast<const char*>(&version), sizeof(version));
        std::ofstream(file, std::ios::binary | std::ios::trunc) << bytes;
        const std::string expected =
            version < written ? "restart file written by an earlier version of fpmshell (format " +
                                    std::to_string(version) + ", this version reads format " +
                                    std::to_string(written) +
                                    "): the run cannot be resumed with this version and must be "
                                    "restarted from the beginning (without --resume)"
                              : "restart file written by a later version of fpmshell (format " +
                                    std::to_string(version) + ", this version reads format " +
                                    std::to_string(written) + ")";
        try {
            (void)run_model(model, second);
            ADD_FAILURE() << "resumed a restart file of format " << version;
        } catch (const InputError& e) {
            const std::string what = e.what();
            EXPECT_NE(what.find(file.string()), std::string::npos) << what;
            EXPECT_NE(what.find(expected), std::string::npos) << what;
        }
    }
    fs::remove_all(first.output_dir);
}

TEST(Restart, ARestartFileDoesNotResumeAnotherModel) {
    RunOptions first;
    first.output_dir = fresh_dir("other");
    first.echo = false;
    first.quiet = true;
    first.stop_at_step = 20;
    ASSERT_EQ(run_model(small_tube(1e-4), first), 0);
    RunOptions second = first;
    second.stop_at_step = 0;
    second.resume = true;
    try {
        (void)run_model(small_tube(1e-4, 5), second);
        ADD_FAILURE() << "resumed a restart file of another mesh";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("restart.bin"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("another model"), std::string::npos) << e.what();
    }
    // The refused resume left the run's results as they were.
    EXPECT_NE(bytes_of(first.output_dir / "fields.pvd").find("frame_00000.vtu"), std::string::npos);
    EXPECT_TRUE(fs::exists(first.output_dir / "fields" / "frame_00000.vtu"));
    fs::remove_all(first.output_dir);
}

TEST(Restart, TheTubeWritesTheSameResultsOnOneAndTwoThreads) {
    // 24 x 24 divisions: 2 304 triangles, above the size where the loops run in parallel; the
    // block presses on the tube from the first step (rigid-body contact, plasticity).
    const Model model = small_tube(4e-5, 24);
    RunOptions one;
    one.output_dir = fresh_dir("threads1");
    one.echo = false;
    one.quiet = true;
    one.threads = 1;
    ASSERT_EQ(run_model(model, one), 0);
    RunOptions two = one;
    two.output_dir = fresh_dir("threads2");
    two.threads = 2;
    ASSERT_EQ(run_model(model, two), 0);
    for (const char* file : {"history.csv", "energy.csv"})
        EXPECT_EQ(bytes_of(one.output_dir / file), bytes_of(two.output_dir / file)) << file;
    fs::remove_all(one.output_dir);
    fs::remove_all(two.output_dir);
}

// The ties' state (theory.md §6.12): plate_hammer.yaml with the doubler glued to the plate by
// tiebreaks instead of welds, stopped after the hammer has torn some ties off (step 700, the
// blow at about step 545) and resumed: the same bytes as the run that never stopped.
/// The model run straight, and stopped at step `stop` then resumed from its restart file: the
/// same history.csv and energy.csv bytes.
void expect_resume_bit_for_bit(const Model& model, const std::string& name, long stop) {
    RunOptions straight;
    straight.output_dir = fresh_dir("straight_" + name);
    straight.echo = false;
    straight.quiet = true;
    ASSERT_EQ(run_model(model, straight), 0);
    RunOptions first = straight;
    first.output_dir = fresh_dir("pieces_" + name);
    first.stop_at_step = stop;
    ASSERT_EQ(run_model(model, first), 0);
    RunOptions second = first;
    second.stop_at_step = 0;
    second.resume = true;
    ASSERT_EQ(run_model(model, second), 0);
    for (const char* file : {"history.csv", "energy.csv"})
        EXPECT_EQ(bytes_of(first.output_dir / file), bytes_of(straight.output_dir / file)) << file;
    fs::remove_all(straight.output_dir);
    fs::remove_all(first.output_dir);
}

TEST(Restart, BrokenTiesResumeBitForBit) {
    Model model = read_model(std::string(FPMSHELL_SOURCE_DIR) +
                             "/examples/decks/plate_hammer/plate_hammer.yaml");
    model.nodal_rigid_bodies.resize(1);  // the plate's rigid edge; the four welds go
    TiedSurface glue;
    glue.nodes = model.node_sets.at("part_2");
    glue.elements = model.element_sets.at("part_1");
    glue.tolerance = 0.004;   // the doubler lies 3.5 mm above the plate
    glue.normal_force = 600;  // N: 17 of the 25 ties let go by step 700
    glue.shear_force = 300;
    model.tied_surfaces.push_back(glue);
    {
        ExplicitSolver probe(model);
        while (probe.steps() < 700) probe.step(1e30);
        ASSERT_GT(probe.tied_surfaces()->broken(), 0u) << "no tie let go before the stop";
        ASSERT_LT(probe.tied_surfaces()->broken(), probe.tied_surfaces()->tied());
    }
    expect_resume_bit_for_bit(model, "ties", 700);
}

TEST(Restart, ARigidSolidResumesBitForBit) {
    // the block of solids in the middle of its impact (contact from step 85): its angular
    // momentum is stepped from the state (w on a particle, x^{n-1}), nothing of its own kept
    Model model =
        read_model(std::string(FPMSHELL_SOURCE_DIR) + "/examples/decks/block_drop/block_drop.yaml");
    model.initial_conditions[0].spin = Vec3(30, 0, 20);  // a spin too: every part of (6.11-12)
    model.initial_conditions[0].spin_about_mass_centre = true;
    expect_resume_bit_for_bit(model, "solid", 300);
}

TEST(Restart, ErosionResumesBitForBit) {
    // the plate torn along its weak band (eroding_band.hpp), stopped at step 193, amid the
    // erosion (its 64 band elements erode from step 185 to 196): the eroded elements, their
    // works and the loads of the step they eroded in carry over
    Model model = test::eroding_band_plate(16);
    model.title = "eroding band";
    model.source_file = (fs::temp_directory_path() / "eroding_band.yaml").string();  // its name
    {
        ExplicitSolver probe(model);
        while (probe.steps() < 193) probe.step(1e30);
        ASSERT_GT(probe.eroded_elements(), 0) << "no element eroded before the stop";
        ASSERT_LT(probe.eroded_elements(), 64);
    }
    expect_resume_bit_for_bit(model, "erosion", 193);
}

TEST(Restart, DamageResumesBitForBit) {
    // the band failing by Johnson-Cook damage, stopped amid its erosion: every point's damage
    // and its plastic strain at the last step carry over
    Model model = test::eroding_band_plate(16, true);
    model.title = "damaging band";
    model.source_file = (fs::temp_directory_path() / "damaging_band.yaml").string();  // its name
    long stop = 0;
    {
        ExplicitSolver probe(model);
        while (probe.eroded_elements() == 0) probe.step(1e30);
        stop = probe.steps() + 3;
        while (probe.steps() < stop) probe.step(1e30);
        ASSERT_LT(probe.eroded_elements(), 64) << "the band must still be eroding at the stop";
    }
    expect_resume_bit_for_bit(model, "damage", stop);
}

TEST(Restart, FadingResumesBitForBit) {
    // the band failing by GISSMO's damage, its stress fading from the start (DCRIT 0), stopped
    // while its points fade, before the first erosion: every point's fading, next and applied,
    // carries over
    Model model = test::eroding_band_plate(16);
    TabulatedFailureParameters gissmo;
    gissmo.failure_strain = {{-1.0, 0.06}, {1.0, 0.04}};
    gissmo.exponent = 2;
    gissmo.fading = TabulatedFailureParameters::Fading{};
    model.materials[1].failure.criteria = {{"tabulated", gissmo}};
    model.title = "fading band";
    model.source_file = (fs::temp_directory_path() / "fading_band.yaml").string();  // its name
    long stop = 0;
    {
        ExplicitSolver probe(model);
        while (probe.eroded_elements() == 0) probe.step(1e30);
        stop = probe.steps() - 4;
        ASSERT_GT(stop, 20);
    }
    expect_resume_bit_for_bit(model, "fading", stop);
}

TEST(Restart, WeldsFailingResumeBitForBit) {
    // a lap joint pulled apart, stopped after its first welds let go and before the last: the
    // failed welds stay failed (the bodies are formed again without them)
    NodalRigidBody::Failure failure;
    failure.shear_force = 4e3;
    test::LapJoint joint = test::lap_joint(2, 6e4, failure);
    Model& model = joint.model;
    model.title = "lap joint";
    model.control.end_time = 3e-3;
    model.source_file = (fs::temp_directory_path() / "lap_joint.yaml").string();  // its name
    long stop = 0;
    {
        ExplicitSolver probe(model);
        while (probe.nodal_rigid_bodies().failed_welds() == 0) probe.step(1e30);
        stop = probe.steps() + 1;
        while (probe.steps() < stop) probe.step(1e30);
        ASSERT_LT(probe.nodal_rigid_bodies().failed_welds(), 6u)
            << "the welds must still be failing at the stop";
    }
    expect_resume_bit_for_bit(model, "welds", stop);
}

TEST(Restart, APerforationResumesBitForBit) {
    // examples/plate_perforation stopped while the ball tears through (its elements erode from
    // about step 50): the faces eroded before the stop leave the self-contact of the resumed run
    const Model model =
        read_model(std::string(FPMSHELL_SOURCE_DIR) + "/examples/plate_perforation/model.yaml");
    {
        ExplicitSolver probe(model);
        while (probe.steps() < 120) probe.step(1e30);
        ASSERT_GT(probe.eroded_elements(), 0) << "no element eroded before the stop";
    }
    expect_resume_bit_for_bit(model, "perforation", 120);
}

}  // namespace
}  // namespace fpmshell
