// Unit tests of the result writers (model-format.md "Results in DIR"): atomic replacement,
// VTU/PVD structure, CSV round trip, JSON text, the output-folder rules, log and progress.
#include <gtest/gtest.h>
#include <unistd.h>
#include <zlib.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <regex>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

#include "fpmshell/core/errors.hpp"
#include "fpmshell/io/atomic_file.hpp"
#include "fpmshell/io/csv_table.hpp"
#include "fpmshell/io/progress.hpp"
#include "fpmshell/io/run_directory.hpp"
#include "fpmshell/io/summary_json.hpp"
#include "fpmshell/io/vtu_writer.hpp"

namespace fs = std::filesystem;
using namespace fpmshell;

namespace {

/// A fresh empty folder under the system temporary folder, removed when the test ends.
class TempDir {
public:
    TempDir() {
        static std::atomic<int> counter{0};
        const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
        path_ = fs::temp_directory_path() /
                ("fpmshell_io_" + std::string(info->name()) + "_" + std::to_string(::getpid()) +
                 "_" + std::to_string(counter++));
        fs::remove_all(path_);
        fs::create_directories(path_);
    }
    ~TempDir() {
        std::error_code ec;
        fs::remove_all(path_, ec);
    }
    [[nodiscard]] const fs::path& path() const { return path_; }

private:
    fs::path path_;
};

std::string read_text(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

std::vector<std::string> files_in(const fs::path& dir) {
    std::vector<std::string> names;
    for (const auto& e : fs::directory_iterator(dir)) names.push_back(e.path().filename().string());
    return names;
}

/// Minimal XML well-formedness check: every start tag is closed in order, the prolog is the
/// XML declaration, and there is exactly one root element. Returns "" or the first problem.
std::string check_xml(const std::string& xml) {
    std::vector<std::string> stack;
    std::size_t pos = 0;
    int roots = 0;
    if (xml.rfind("<?xml", 0) != 0) return "no XML declaration";
    pos = xml.find("?>") + 2;
    while ((pos = xml.find('<', pos)) != std::string::npos) {
        const std::size_t end = xml.find('>', pos);
        if (end == std::string::npos) return "unterminated tag";
        std::string tag = xml.substr(pos + 1, end - pos - 1);
        pos = end + 1;
        if (tag.empty()) return "empty tag";
        if (tag[0] == '/') {
            if (stack.empty() || stack.back() != tag.substr(1)) return "mismatched </" + tag + ">";
            stack.pop_back();
            continue;
        }
        const bool self_closing = tag.back() == '/';
        const std::string name = tag.substr(0, tag.find_first_of(" /\n"));
        if (stack.empty()) ++roots;
        if (!self_closing) stack.push_back(name);
    }
    if (!stack.empty()) return "unclosed <" + stack.back() + ">";
    if (roots != 1) return "not exactly one root element";
    return {};
}

std::vector<unsigned char> base64_decode(const std::string& text) {
    auto value = [](char c) -> int {
        if (c >= 'A' && c <= 'Z') return c - 'A';
        if (c >= 'a' && c <= 'z') return c - 'a' + 26;
        if (c >= '0' && c <= '9') return c - '0' + 52;
        if (c == '+') return 62;
        if (c == '/') return 63;
        return -1;
    };
    std::vector<unsigned char> out;
    std::uint32_t buffer = 0;
    int bits = 0;
    for (const char c : text) {
        const int v = value(c);
        if (v < 0) continue;  // whitespace and '=' padding
        buffer = (buffer << 6) | static_cast<std::uint32_t>(v);
        bits += 6;
        if (bits >= 8) {
            bits -= 8;
            out.push_back(static_cast<unsigned char>((buffer >> bits) & 0xFF));
        }
    }
    return out;
}

/// Body of the DataArray called `name` in a VTU text ("" when missing).
std::string data_array_body(const std::string& xml, const std::string& name) {
    const std::size_t at = xml.find("Name=\"" + name + "\"");
    if (at == std::string::npos) return {};
    const std::size_t begin = xml.find('>', at) + 1;
    const std::size_t end = xml.find("</DataArray>", begin);
    return xml.substr(begin, end - begin);
}

/// Decodes a base64 DataArray body: UInt64 byte count, then that many bytes of T.
template <class T>
std::vector<T> decode_array(const std::string& body) {
    const std::vector<unsigned char> bytes = base64_decode(body);
    std::uint64_t n = 0;
    std::memcpy(&n, bytes.data(), sizeof(n));
    EXPECT_EQ(bytes.size(), sizeof(n) + n);
    std::vector<T> values(n / sizeof(T));
    if (n > 0) std::memcpy(values.data(), bytes.data() + sizeof(n), n);  // data() may be null
    return values;
}

/// The bytes at `offset` of the AppendedData block of a raw .vtu text.
std::string_view appended_bytes(const std::string& text, const std::string& name) {
    const std::size_t at = text.find("Name=\"" + name + "\"");
    if (at == std::string::npos) return {};
    const std::size_t offset_at = text.find("offset=\"", at) + 8;
    const std::size_t offset = std::stoul(text.substr(offset_at, 20));
    const std::size_t data = text.find('_', text.find("<AppendedData encoding=\"raw\">")) + 1;
    return std::string_view(text).substr(data + offset);
}

/// The UInt64 compression header of array `name` in a zlib-compressed raw .vtu text.
std::vector<std::uint64_t> zlib_header(const std::string& text, const std::string& name) {
    const std::string_view bytes = appended_bytes(text, name);
    std::uint64_t blocks = 0;
    std::memcpy(&blocks, bytes.data(), sizeof blocks);
    std::vector<std::uint64_t> header(3 + blocks);
    std::memcpy(header.data(), bytes.data(), header.size() * sizeof(std::uint64_t));
    return header;
}

/// The values of array `name` of a raw .vtu text: [UInt64 byte count][values] at its offset, or
/// (zlib) the header of zlib_header and the blocks, inflated.
template <class T>
std::vector<T> appended_array(const std::string& text, const std::string& name, bool zlib = false) {
    const std::string_view bytes = appended_bytes(text, name);
    std::string values;
    if (!zlib) {
        std::uint64_t n = 0;
        std::memcpy(&n, bytes.data(), sizeof n);
        values = bytes.substr(sizeof n, n);
    } else {
        const std::vector<std::uint64_t> header = zlib_header(text, name);
        std::size_t at = header.size() * sizeof(std::uint64_t);
        for (std::size_t b = 0; b < header[0]; ++b) {
            const bool last = b + 1 == header[0] && header[2] != 0;
            uLongf size = last ? header[2] : header[1];
            std::string block(size, '\0');
            EXPECT_EQ(
                ::uncompress(reinterpret_cast<Bytef*>(block.data()), &size,
                             reinterpret_cast<const Bytef*>(bytes.data() + at), header[3 + b]),
                Z_OK);
            values += block.substr(0, size);
            at += header[3 + b];
        }
    }
    std::vector<T> out(values.size() / sizeof(T));
    if (!out.empty()) std::memcpy(out.data(), values.data(), values.size());
    return out;
}

FieldFrame two_triangle_frame() {
    FieldFrame f;
    f.time = 2.5e-4;
    f.points = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0.5), Vec3(0, 1, 0)};
    f.triangles = {{0, 1, 2}, {0, 2, 3}};
    f.point_data.push_back({"displacement", 3, std::vector<Real>(12, 0.0)});
    f.point_data[0].values[8] = -0.125;  // uz of point 2
    f.point_data.push_back({"thickness", 1, {0.1, 0.1, 0.2, 0.1}});
    f.cell_data.push_back({"plastic_strain_top", 1, {0.0, 0.03}});
    return f;
}

}  // namespace

// Proves write_file_atomic replaces the whole content and leaves no temporary file behind.
TEST(AtomicFile, ReplacesContentAndLeavesNoTemporary) {
    TempDir tmp;
    const fs::path file = tmp.path() / "a.txt";
    write_file_atomic(file, "first version, rather long\n");
    write_file_atomic(file, "second\n");
    EXPECT_EQ(read_text(file), "second\n");
    EXPECT_EQ(files_in(tmp.path()), std::vector<std::string>{"a.txt"});
}

// Proves a write into a missing folder throws a sentence naming the file, and leaves nothing.
TEST(AtomicFile, FailureNamesTheFile) {
    TempDir tmp;
    const fs::path file = tmp.path() / "missing" / "a.txt";
    try {
        write_file_atomic(file, "x");
        FAIL() << "no exception";
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find(file.string()), std::string::npos) << e.what();
    }
    EXPECT_TRUE(files_in(tmp.path()).empty());
}

// Proves the base64 VTU text is well-formed XML with the right counts, triangle cells (type 5),
// and arrays that decode back to the frame's numbers.
TEST(VtuWriter, WellFormedWithRightCountsAndValues) {
    TempDir tmp;
    const FieldFrame f = two_triangle_frame();
    const fs::path file = tmp.path() / "frame_00000.vtu";
    write_vtu(file, f, VtuEncoding::Base64);
    const std::string xml = read_text(file);

    EXPECT_EQ(check_xml(xml), "");
    EXPECT_NE(xml.find("type=\"UnstructuredGrid\""), std::string::npos);
    EXPECT_NE(xml.find("NumberOfPoints=\"4\" NumberOfCells=\"2\""), std::string::npos);
    EXPECT_NE(xml.find("Name=\"displacement\" NumberOfComponents=\"3\""), std::string::npos);

    const auto points = decode_array<double>(data_array_body(xml, "Points"));
    ASSERT_EQ(points.size(), 12u);
    EXPECT_EQ(points[8], 0.5);  // z of point 2
    EXPECT_EQ(decode_array<std::int32_t>(data_array_body(xml, "connectivity")),
              (std::vector<std::int32_t>{0, 1, 2, 0, 2, 3}));
    EXPECT_EQ(decode_array<std::int64_t>(data_array_body(xml, "offsets")),
              (std::vector<std::int64_t>{3, 6}));
    EXPECT_EQ(decode_array<std::uint8_t>(data_array_body(xml, "types")),
              (std::vector<std::uint8_t>{5, 5}));
    EXPECT_EQ(decode_array<double>(data_array_body(xml, "displacement"))[8], -0.125);
    EXPECT_EQ(decode_array<double>(data_array_body(xml, "plastic_strain_top"))[1], 0.03);
    EXPECT_NE(data_array_body(xml, "TimeValue").find("0.00025"), std::string::npos);
}

// Proves the ASCII encoding is well-formed XML holding the values as decimal text.
TEST(VtuWriter, AsciiEncoding) {
    const std::string xml = vtu_text(two_triangle_frame(), VtuEncoding::Ascii);
    EXPECT_EQ(check_xml(xml), "");
    std::istringstream conn(data_array_body(xml, "connectivity"));
    std::vector<int> ids;
    for (int v; conn >> v;) ids.push_back(v);
    EXPECT_EQ(ids, (std::vector<int>{0, 1, 2, 0, 2, 3}));
    EXPECT_NE(data_array_body(xml, "displacement").find("-0.125"), std::string::npos);
}

// Proves inconsistent frames (wrong array length, triangle naming a missing point) are refused.
TEST(VtuWriter, RejectsInconsistentFrames) {
    FieldFrame f = two_triangle_frame();
    f.point_data[1].values.pop_back();
    EXPECT_THROW((void)vtu_text(f), std::invalid_argument);
    f = two_triangle_frame();
    f.triangles[1][2] = 4;
    EXPECT_THROW((void)vtu_text(f), std::invalid_argument);
}

// Proves the default (raw appended) file: every array format="appended" at an offset into the
// AppendedData block, where its byte count and the frame's values lie, in the order of the XML;
// the file written is the text.
TEST(VtuWriter, RawAppendedArraysLieAtTheirOffsets) {
    TempDir tmp;
    const FieldFrame f = two_triangle_frame();
    const std::string text = vtu_text(f);
    write_vtu(tmp.path() / "frame.vtu", f);
    EXPECT_EQ(read_text(tmp.path() / "frame.vtu"), text);
    EXPECT_EQ(text.find("format=\"binary\""), std::string::npos);
    EXPECT_EQ(check_xml(text.substr(0, text.find("<AppendedData")) + "</VTKFile>\n"), "");
    EXPECT_TRUE(text.ends_with("\n  </AppendedData>\n</VTKFile>\n"));

    EXPECT_EQ(appended_array<double>(text, "Points")[8], 0.5);
    EXPECT_EQ(appended_array<std::int32_t>(text, "connectivity"),
              (std::vector<std::int32_t>{0, 1, 2, 0, 2, 3}));
    EXPECT_EQ(appended_array<std::int64_t>(text, "offsets"), (std::vector<std::int64_t>{3, 6}));
    EXPECT_EQ(appended_array<std::uint8_t>(text, "types"), (std::vector<std::uint8_t>{5, 5}));
    EXPECT_EQ(appended_array<double>(text, "displacement"), f.point_data[0].values);
    EXPECT_EQ(appended_array<double>(text, "thickness"), f.point_data[1].values);
    EXPECT_EQ(appended_array<double>(text, "plastic_strain_top"), f.cell_data[0].values);
}

// Proves zlib compression: VTK's block header (blocks of 32 768 bytes, the last one partial) and
// blocks that inflate back to the raw file's bytes, for an array of several blocks, one of one
// block and an empty frame.
TEST(VtuWriter, ZlibBlocksInflateToTheRawArrays) {
    FieldFrame f = two_triangle_frame();
    f.points.resize(10000, Vec3(0.25, 0.5, 0.75));  // 240 000 bytes: 8 blocks
    f.point_data[0].values.resize(3 * 10000, 1.0);
    f.point_data[1].values.resize(10000, 0.2);
    std::vector<Real> ramp(10000);  // 80 000 bytes: 3 blocks, the last one partial
    for (std::size_t i = 0; i < ramp.size(); ++i) ramp[i] = 1e-3 * static_cast<Real>(i);
    f.point_data.push_back({"long", 1, ramp});
    const std::string raw = vtu_text(f);
    const std::string zlib = vtu_text(f, {VtuEncoding::Raw, VtuCompression::Zlib});
    EXPECT_NE(zlib.find("compressor=\"vtkZLibDataCompressor\""), std::string::npos);
    EXPECT_LT(zlib.size(), raw.size() / 2);  // the constant arrays compress to almost nothing
    const std::vector<std::uint64_t> header = zlib_header(zlib, "long");
    ASSERT_EQ(header.size(), 6u);
    EXPECT_EQ(header[0], 3u);
    EXPECT_EQ(header[1], 32768u);
    EXPECT_EQ(header[2], 80000u - 2 * 32768u);
    for (const char* name : {"Points", "displacement", "thickness", "long", "plastic_strain_top"})
        EXPECT_EQ(appended_array<double>(zlib, name, true), appended_array<double>(raw, name))
            << name;
    EXPECT_EQ(appended_array<std::int32_t>(zlib, "connectivity", true),
              (std::vector<std::int32_t>{0, 1, 2, 0, 2, 3}));

    const std::string empty = vtu_text(FieldFrame{}, {VtuEncoding::Raw, VtuCompression::Zlib});
    EXPECT_EQ(zlib_header(empty, "Points"), (std::vector<std::uint64_t>{0, 32768, 0}));
    EXPECT_TRUE(appended_array<double>(empty, "Points", true).empty());
    EXPECT_THROW((void)vtu_text(f, {VtuEncoding::Base64, VtuCompression::Zlib}),
                 std::invalid_argument);
}

// Proves an empty frame still gives a valid file in every encoding (a model with no elements
// cannot crash output).
TEST(VtuWriter, EmptyFrame) {
    const std::string xml = vtu_text(FieldFrame{}, VtuEncoding::Base64);
    EXPECT_EQ(check_xml(xml), "");
    EXPECT_TRUE(decode_array<double>(data_array_body(xml, "Points")).empty());
    EXPECT_EQ(check_xml(vtu_text(FieldFrame{}, VtuEncoding::Ascii)), "");
    const std::string raw = vtu_text(FieldFrame{});
    EXPECT_TRUE(appended_array<double>(raw, "Points").empty());
    EXPECT_TRUE(appended_array<std::uint8_t>(raw, "types").empty());
}

// Proves the PVD lists every frame added, in order, with its time, and is valid XML each time.
TEST(PvdSeries, ListsAllFrames) {
    TempDir tmp;
    const fs::path pvd = tmp.path() / "fields.pvd";
    {
        std::ofstream stale(pvd);
        stale << "old series";
    }
    PvdSeries series(pvd);
    EXPECT_EQ(check_xml(read_text(pvd)), "");
    EXPECT_EQ(read_text(pvd).find("DataSet"), std::string::npos);  // the stale list is gone
    for (int i = 0; i < 3; ++i) {
        series.add(1e-4 * i, "fields/frame_0000" + std::to_string(i) + ".vtu");
        EXPECT_EQ(check_xml(read_text(pvd)), "");
    }
    const std::string xml = read_text(pvd);
    std::regex dataset(R"re(<DataSet timestep="([^"]+)"[^>]*file="([^"]+)"/>)re");
    std::vector<std::string> files;
    std::vector<double> times;
    for (auto it = std::sregex_iterator(xml.begin(), xml.end(), dataset);
         it != std::sregex_iterator(); ++it) {
        times.push_back(std::stod((*it)[1]));
        files.push_back((*it)[2]);
    }
    EXPECT_EQ(files, (std::vector<std::string>{"fields/frame_00000.vtu", "fields/frame_00001.vtu",
                                               "fields/frame_00002.vtu"}));
    EXPECT_EQ(times, (std::vector<double>{0.0, 1e-4, 2e-4}));
    EXPECT_EQ(series.size(), 3u);
}

// Proves the .pvtu of a frame in pieces is well-formed XML that declares the frame's arrays with
// their components, in order, and lists the pieces by their paths.
TEST(PvtuWriter, DeclaresTheArraysAndListsThePieces) {
    TempDir tmp;
    const fs::path file = tmp.path() / "frame_00003.pvtu";
    const FieldFrame frame = two_triangle_frame();
    write_pvtu(file, frame, {"frame_00003_rank0.vtu", "frame_00003_rank1.vtu"});
    const std::string xml = read_text(file);
    EXPECT_EQ(check_xml(xml), "");
    EXPECT_NE(xml.find("type=\"PUnstructuredGrid\""), std::string::npos);
    EXPECT_NE(xml.find("header_type=\"UInt64\""), std::string::npos);
    std::regex declared(
        R"re(<PDataArray type="Float64" Name="(\w+)" NumberOfComponents="(\d)"/>)re");
    std::vector<std::string> arrays;
    for (auto it = std::sregex_iterator(xml.begin(), xml.end(), declared);
         it != std::sregex_iterator(); ++it)
        arrays.push_back((*it)[1].str() + "/" + (*it)[2].str());
    std::vector<std::string> expected;
    for (const auto* list : {&frame.point_data, &frame.cell_data})
        for (const FieldArray& a : *list)
            expected.push_back(a.name + "/" + std::to_string(a.components));
    expected.emplace_back("Points/3");
    EXPECT_EQ(arrays, expected);
    EXPECT_LT(xml.find("<Piece Source=\"frame_00003_rank0.vtu\"/>"),
              xml.find("<Piece Source=\"frame_00003_rank1.vtu\"/>"));
}

// Proves a resumed run's clean-up removes the frames from a number on in every form: whole
// frames, the .pvtu of a distributed run and its pieces, and leftover temporary files.
TEST(RunDirectory, RemovesFramesFromANumberOnWholeOrInPieces) {
    TempDir tmp;
    const fs::path fields = tmp.path() / "fields";
    fs::create_directories(fields);
    const std::vector<std::string> names{"frame_00000.pvtu",           "frame_00000_rank0.vtu",
                                         "frame_00000_rank1.vtu",      "frame_00001.vtu",
                                         "frame_00002.pvtu",           "frame_00002_rank0.vtu",
                                         "frame_00002_rank1.vtu",      "frame_00003.vtu",
                                         "frame_00001.pvtu.tmp.12",    "notes.txt",
                                         "frame_00003_rank2.vtu.tmp.7"};
    for (const std::string& n : names) write_file_atomic(fields / n, "<x/>");
    remove_frames_from(tmp.path(), 2);
    std::vector<std::string> left;
    for (const auto& entry : fs::directory_iterator(fields))
        left.push_back(entry.path().filename().string());
    std::sort(left.begin(), left.end());
    EXPECT_EQ(left,
              (std::vector<std::string>{"frame_00000.pvtu", "frame_00000_rank0.vtu",
                                        "frame_00000_rank1.vtu", "frame_00001.vtu", "notes.txt"}));
}

// Proves a CSV table reads back with the same header and values (10 significant digits),
// including NaN, and that each flush rewrites the whole file.
TEST(CsvTable, RoundTrip) {
    TempDir tmp;
    const fs::path file = tmp.path() / "history.csv";
    CsvTable table({"time", "apex_w", "rim_fz"});
    table.add_row({0.0, 0.0, 0.0});
    table.flush(file);
    table.add_row({1e-6, -1.234567890123e-3, 600.5});
    table.add_row({2e-6, std::numeric_limits<Real>::quiet_NaN(), -1e30});
    table.flush(file);

    EXPECT_EQ(read_text(file).substr(0, 19), "time,apex_w,rim_fz\n");
    const CsvTable back = CsvTable::read(file);
    EXPECT_EQ(back.header(), table.header());
    ASSERT_EQ(back.n_rows(), 3u);
    EXPECT_DOUBLE_EQ(back.rows()[1][1], -1.234567890e-3);  // 10 significant digits kept
    EXPECT_NEAR(back.rows()[1][1], -1.234567890123e-3, 1e-12);
    EXPECT_TRUE(std::isnan(back.rows()[2][1]));
    EXPECT_EQ(back.rows()[2][2], -1e30);
    EXPECT_EQ(back.column(*back.column_index("rim_fz")), (std::vector<Real>{0.0, 600.5, -1e30}));
    EXPECT_THROW(table.add_row({1.0}), std::invalid_argument);
}

// Proves the shortest-round-trip mode (digits 0) keeps every double exactly.
TEST(CsvTable, FullPrecisionMode) {
    TempDir tmp;
    CsvTable table({"x"}, 0);
    const Real x = 0.1 + 0.2;
    table.add_row({x});
    table.flush(tmp.path() / "t.csv");
    EXPECT_EQ(CsvTable::read(tmp.path() / "t.csv").rows()[0][0], x);
}

// Proves JSON strings are escaped (quote, backslash, control characters), NaN and infinity
// become null, numbers round-trip, and object keys keep their insertion order.
TEST(SummaryJson, EscapingNumbersAndOrder) {
    JsonValue v = JsonValue::object();
    v["title"] = "cap \"quarter\" \\ tab\there\nnew\x01";
    v["energy_error"] = std::numeric_limits<double>::quiet_NaN();
    v["wall_seconds"] = std::numeric_limits<double>::infinity();
    v["steps"] = 12345;
    v["end_time"] = 0.1 + 0.2;
    v["ok"] = true;
    v["peaks"]["apex_w"]["value"] = -0.5;
    v["list"].push_back(1);
    v["list"].push_back(nullptr);

    const std::string compact = to_json(v, 0);
    EXPECT_EQ(compact,
              "{\"title\":\"cap \\\"quarter\\\" \\\\ tab\\there\\nnew\\u0001\","
              "\"energy_error\":null,\"wall_seconds\":null,\"steps\":12345,"
              "\"end_time\":0.30000000000000004,\"ok\":true,"
              "\"peaks\":{\"apex_w\":{\"value\":-0.5}},\"list\":[1,null]}");
    const std::string pretty = to_json(v);
    EXPECT_NE(pretty.find("\n  \"steps\": 12345,\n"), std::string::npos) << pretty;
    EXPECT_EQ(to_json(JsonValue::object()), "{}");
    EXPECT_EQ(json_quote("\xc3\xa9"), "\"\xc3\xa9\"");  // UTF-8 passes through
}

// Proves a run into a folder holding another model's results is refused with a sentence naming
// the folder and --overwrite, while the same model or --overwrite are accepted and clean up.
TEST(RunDirectory, RefusesAnotherModelAcceptsSameOrOverwrite) {
    TempDir tmp;
    const fs::path dir = tmp.path() / "results" / "cap";
    const fs::path model_a = tmp.path() / "a.yaml";
    const fs::path model_b = tmp.path() / "b.yaml";
    std::ofstream(model_a) << "title: a\n";
    std::ofstream(model_b) << "title: b\n";

    prepare_run_directory(dir, model_a, false);  // creates it, with fields/
    ASSERT_TRUE(fs::is_directory(dir / "fields"));
    write_file_atomic(dir / "history.csv", "time\n0\n");
    write_file_atomic(dir / "fields" / "frame_00000.vtu", "<x/>");
    write_file_atomic(dir / "notes.txt", "the user's own file");

    try {
        prepare_run_directory(dir, model_b, false);
        FAIL() << "another model's results were taken over";
    } catch (const InputError& e) {
        const std::string msg = e.what();
        EXPECT_NE(msg.find(dir.string()), std::string::npos) << msg;
        EXPECT_NE(msg.find("--overwrite"), std::string::npos) << msg;
    }
    EXPECT_TRUE(fs::exists(dir / "history.csv"));  // nothing was touched

    prepare_run_directory(dir, model_a, false);  // same model: old results go
    EXPECT_FALSE(fs::exists(dir / "history.csv"));
    EXPECT_FALSE(fs::exists(dir / "fields" / "frame_00000.vtu"));
    EXPECT_TRUE(fs::exists(dir / "notes.txt"));

    write_file_atomic(dir / "summary.json", "{}");
    prepare_run_directory(dir, model_b, true);  // --overwrite
    EXPECT_FALSE(fs::exists(dir / "summary.json"));
    EXPECT_NE(read_text(dir / k_model_marker).find("b.yaml"), std::string::npos);
    EXPECT_TRUE(fs::exists(dir / "notes.txt"));
}

// Proves results without a marker (unknown model) are refused, and a file given as DIR too.
TEST(RunDirectory, RefusesUnknownResultsAndFiles) {
    TempDir tmp;
    const fs::path model = tmp.path() / "m.yaml";
    std::ofstream(model) << "title: m\n";
    const fs::path dir = tmp.path() / "out";
    fs::create_directories(dir);
    std::ofstream(dir / "summary.json") << "{}";
    EXPECT_THROW(prepare_run_directory(dir, model, false), InputError);
    std::ofstream(tmp.path() / "plain") << "x";
    EXPECT_THROW(prepare_run_directory(tmp.path() / "plain", model, true), InputError);
}

// Proves LogFile keeps every line in log.txt, appending within a run.
TEST(LogFile, WritesEveryLine) {
    TempDir tmp;
    {
        LogFile log(tmp.path() / "log.txt", false);
        log.line("first");
        log.print("step {} dt {:.1e}", 3, 1e-6);
        EXPECT_EQ(read_text(tmp.path() / "log.txt"), "first\nstep 3 dt 1.0e-06\n");
    }
    LogFile again(tmp.path() / "log.txt", false);
    again.write("more\n");
    EXPECT_EQ(read_text(tmp.path() / "log.txt"), "first\nstep 3 dt 1.0e-06\nmore\n");
}

// Proves plain progress prints about one line per 5 % of end_time, ending at 100 %.
TEST(Progress, PlainLinesEveryFivePercent) {
    std::vector<std::string> lines;
    {
        Progress p(
            1.0, true, [&](const std::string& s) { lines.push_back(s); }, false);
        for (long step = 1; step <= 1000; ++step) p.update(step * 1e-3, step, 1e-3, 1e-4);
        p.finish();
        p.finish();
    }
    EXPECT_EQ(lines.size(), 20u);
    EXPECT_NE(lines.back().find("100.0 %"), std::string::npos) << lines.back();
    EXPECT_NE(lines.back().find("step 1000"), std::string::npos) << lines.back();
    EXPECT_NE(lines.back().find("energy error 0.010 %"), std::string::npos) << lines.back();
}

// Proves a run that stops early still reports its last state once at finish().
TEST(Progress, FinishReportsLastStateOnce) {
    std::vector<std::string> lines;
    Progress p(
        1.0, true, [&](const std::string& s) { lines.push_back(s); }, false);
    p.update(0.03, 3, 0.01, 0.0);
    EXPECT_TRUE(lines.empty());
    p.finish();
    ASSERT_EQ(lines.size(), 1u);
    EXPECT_NE(lines[0].find("step 3"), std::string::npos);
}
