// VTK XML writer for triangle shells; format notes are in vtu_writer.hpp.
#include "fpmshell/io/vtu_writer.hpp"

#include <fmt/format.h>

#include <bit>
#include <cstdint>
#include <cstring>
#include <iterator>
#include <stdexcept>
#include <type_traits>

#include "fpmshell/io/atomic_file.hpp"

namespace fpmshell {

namespace {

constexpr std::uint8_t k_vtk_triangle = 5;

const char* byte_order_name() {
    return std::endian::native == std::endian::little ? "LittleEndian" : "BigEndian";
}

/// Escapes the five XML special characters for use inside an attribute value.
std::string xml_escape(std::string_view s) {
    std::string out;
    out.reserve(s.size());
    for (const char c : s) {
        switch (c) {
            case '&':
                out += "&amp;";
                break;
            case '<':
                out += "&lt;";
                break;
            case '>':
                out += "&gt;";
                break;
            case '"':
                out += "&quot;";
                break;
            case '\'':
                out += "&apos;";
                break;
            default:
                out += c;
        }
    }
    return out;
}

/// Base64 (RFC 4648, with padding) of `n` bytes, appended to `out`.
void append_base64(std::string& out, const unsigned char* bytes, std::size_t n) {
    static constexpr char k_alphabet[] =
        "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    // Sized once and filled through a pointer: a frame of 10^5 triangles is 20 MB of text, and
    // appending it character by character cost more than the time steps between two frames.
    const std::size_t start = out.size();
    out.resize(start + 4 * ((n + 2) / 3));
    char* dst = out.data() + start;
    std::size_t i = 0;
    for (; i + 3 <= n; i += 3) {
        const std::uint32_t v = (std::uint32_t{bytes[i]} << 16) |
                                (std::uint32_t{bytes[i + 1]} << 8) | std::uint32_t{bytes[i + 2]};
        *dst++ = k_alphabet[(v >> 18) & 63];
        *dst++ = k_alphabet[(v >> 12) & 63];
        *dst++ = k_alphabet[(v >> 6) & 63];
        *dst++ = k_alphabet[v & 63];
    }
    if (const std::size_t rest = n - i; rest > 0) {
        std::uint32_t v = std::uint32_t{bytes[i]} << 16;
        if (rest == 2) v |= std::uint32_t{bytes[i + 1]} << 8;
        *dst++ = k_alphabet[(v >> 18) & 63];
        *dst++ = k_alphabet[(v >> 12) & 63];
        *dst++ = rest == 2 ? k_alphabet[(v >> 6) & 63] : '=';
        *dst++ = '=';
    }
}

/// Writes the body of one DataArray: base64 of [UInt64 byte count][values], or ASCII values.
template <class T>
void append_values(std::string& out, const std::vector<T>& values, VtuEncoding encoding) {
    if (encoding == VtuEncoding::Ascii) {
        for (std::size_t i = 0; i < values.size(); ++i) {
            if (i > 0) out += (i % 9 == 0) ? '\n' : ' ';
            if constexpr (std::is_same_v<T, std::uint8_t>) {
                fmt::format_to(std::back_inserter(out), "{}", static_cast<unsigned>(values[i]));
            } else {
                fmt::format_to(std::back_inserter(out), "{}", values[i]);
            }
        }
        return;
    }
    const std::uint64_t n_bytes = values.size() * sizeof(T);
    std::vector<unsigned char> buffer(sizeof(n_bytes) + n_bytes);
    std::memcpy(buffer.data(), &n_bytes, sizeof(n_bytes));
    if (n_bytes > 0) std::memcpy(buffer.data() + sizeof(n_bytes), values.data(), n_bytes);
    append_base64(out, buffer.data(), buffer.size());
}

template <class T>
void append_data_array(std::string& out, const char* type, const std::string& name, int components,
                       const std::vector<T>& values, VtuEncoding encoding, const char* indent) {
    fmt::format_to(std::back_inserter(out), "{}<DataArray type=\"{}\" Name=\"{}\"", indent, type,
                   xml_escape(name));
    if (components > 0) {
        fmt::format_to(std::back_inserter(out), " NumberOfComponents=\"{}\"", components);
    }
    fmt::format_to(std::back_inserter(out), " format=\"{}\">\n",
                   encoding == VtuEncoding::Ascii ? "ascii" : "binary");
    append_values(out, values, encoding);
    fmt::format_to(std::back_inserter(out), "\n{}</DataArray>\n", indent);
}

void check_arrays(const std::vector<FieldArray>& arrays, std::size_t n, const char* where) {
    for (const FieldArray& a : arrays) {
        if (a.components < 1) {
            throw std::invalid_argument(
                fmt::format("{} array '{}' has {} components; it needs at least 1.", where, a.name,
                            a.components));
        }
        if (a.values.size() != n * static_cast<std::size_t>(a.components)) {
            throw std::invalid_argument(fmt::format(
                "{} array '{}' holds {} values; {} items x {} components need {}.", where, a.name,
                a.values.size(), n, a.components, n * static_cast<std::size_t>(a.components)));
        }
    }
}

}  // namespace

std::string vtu_text(const FieldFrame& frame, VtuEncoding encoding) {
    const std::size_t n_points = frame.points.size();
    const std::size_t n_cells = frame.triangles.size();
    check_arrays(frame.point_data, n_points, "point data");
    check_arrays(frame.cell_data, n_cells, "cell data");

    std::vector<Real> coords;
    coords.reserve(3 * n_points);
    for (const Vec3& p : frame.points) {
        coords.push_back(p.x());
        coords.push_back(p.y());
        coords.push_back(p.z());
    }
    std::vector<std::int32_t> connectivity;
    connectivity.reserve(3 * n_cells);
    for (std::size_t e = 0; e < n_cells; ++e) {
        for (const Index v : frame.triangles[e]) {
            if (v < 0 || static_cast<std::size_t>(v) >= n_points) {
                throw std::invalid_argument(fmt::format(
                    "triangle {} names point {}, but the frame has {} points.", e, v, n_points));
            }
            connectivity.push_back(static_cast<std::int32_t>(v));
        }
    }
    std::vector<std::int64_t> offsets(n_cells);
    for (std::size_t e = 0; e < n_cells; ++e) offsets[e] = static_cast<std::int64_t>(3 * (e + 1));
    const std::vector<std::uint8_t> types(n_cells, k_vtk_triangle);

    std::string out;
    // Rough size: base64 of 8-byte values is ~11 characters per value.
    std::size_t n_values = coords.size() + connectivity.size() + 2 * n_cells;
    for (const FieldArray& a : frame.point_data) n_values += a.values.size();
    for (const FieldArray& a : frame.cell_data) n_values += a.values.size();
    out.reserve(2048 + 12 * n_values);

    fmt::format_to(std::back_inserter(out),
                   "<?xml version=\"1.0\"?>\n"
                   "<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"{}\" "
                   "header_type=\"UInt64\">\n"
                   "  <UnstructuredGrid>\n"
                   "    <FieldData>\n"
                   "      <DataArray type=\"Float64\" Name=\"TimeValue\" NumberOfTuples=\"1\" "
                   "format=\"ascii\">\n        {}\n      </DataArray>\n"
                   "    </FieldData>\n"
                   "    <Piece NumberOfPoints=\"{}\" NumberOfCells=\"{}\">\n",
                   byte_order_name(), frame.time, n_points, n_cells);

    const char* indent = "        ";
    out += "      <PointData>\n";
    for (const FieldArray& a : frame.point_data) {
        append_data_array(out, "Float64", a.name, a.components, a.values, encoding, indent);
    }
    out += "      </PointData>\n      <CellData>\n";
    for (const FieldArray& a : frame.cell_data) {
        append_data_array(out, "Float64", a.name, a.components, a.values, encoding, indent);
    }
    out += "      </CellData>\n      <Points>\n";
    append_data_array(out, "Float64", "Points", 3, coords, encoding, indent);
    out += "      </Points>\n      <Cells>\n";
    append_data_array(out, "Int32", "connectivity", 0, connectivity, encoding, indent);
    append_data_array(out, "Int64", "offsets", 0, offsets, encoding, indent);
    append_data_array(out, "UInt8", "types", 0, types, encoding, indent);
    out += "      </Cells>\n    </Piece>\n  </UnstructuredGrid>\n</VTKFile>\n";
    return out;
}

void write_vtu(const std::filesystem::path& path, const FieldFrame& frame, VtuEncoding encoding) {
    write_file_atomic(path, vtu_text(frame, encoding));
}

PvdSeries::PvdSeries(std::filesystem::path pvd_path) : pvd_path_(std::move(pvd_path)) { write(); }

void PvdSeries::add(Real time, const std::string& relative_vtu_path) {
    entries_.emplace_back(time, relative_vtu_path);
    write();
}

void PvdSeries::write() const {
    std::string out;
    fmt::format_to(std::back_inserter(out),
                   "<?xml version=\"1.0\"?>\n"
                   "<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"{}\">\n"
                   "  <Collection>\n",
                   byte_order_name());
    for (const auto& [time, file] : entries_) {
        fmt::format_to(std::back_inserter(out),
                       "    <DataSet timestep=\"{}\" group=\"\" part=\"0\" file=\"{}\"/>\n", time,
                       xml_escape(file));
    }
    out += "  </Collection>\n</VTKFile>\n";
    write_file_atomic(pvd_path_, out);
}

}  // namespace fpmshell
