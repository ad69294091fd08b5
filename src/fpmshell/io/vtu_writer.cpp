// VTK XML writer for triangle shells; format notes are in vtu_writer.hpp.
#include "fpmshell/io/vtu_writer.hpp"

#include <fmt/format.h>
#include <zlib.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cstdint>
#include <cstring>
#include <deque>
#include <iterator>
#include <stdexcept>
#include <string_view>
#include <type_traits>
#include <vector>

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

/// One DataArray: its VTK type, name, components (0: the attribute is not written) and values
/// as they lie in memory.
struct Array {
    const char* type;
    std::string_view name;
    int components;
    std::string_view bytes;
};

template <class T>
std::string_view bytes_of(const T* values, std::size_t n) {
    return {reinterpret_cast<const char*>(values), n * sizeof(T)};
}

template <class T>
void append_ascii(std::string& out, std::string_view bytes) {
    const std::size_t n = bytes.size() / sizeof(T);
    for (std::size_t i = 0; i < n; ++i) {
        T v;
        std::memcpy(&v, bytes.data() + i * sizeof(T), sizeof(T));
        if (i > 0) out += (i % 9 == 0) ? '\n' : ' ';
        if constexpr (std::is_same_v<T, std::uint8_t>) {
            fmt::format_to(std::back_inserter(out), "{}", static_cast<unsigned>(v));
        } else {
            fmt::format_to(std::back_inserter(out), "{}", v);
        }
    }
}

void append_ascii(std::string& out, const Array& a) {
    const std::string_view type = a.type;
    if (type == "Float64") return append_ascii<double>(out, a.bytes);
    if (type == "Int32") return append_ascii<std::int32_t>(out, a.bytes);
    if (type == "Int64") return append_ascii<std::int64_t>(out, a.bytes);
    append_ascii<std::uint8_t>(out, a.bytes);
}

std::string byte_count(std::uint64_t n) { return {reinterpret_cast<const char*>(&n), sizeof n}; }

/// zlib's level for the frames: level 1 keeps most of the gain on arrays of doubles (their low
/// mantissa bytes do not compress at any level) at a few times the speed of the default 6.
constexpr int k_zlib_level = 1;
constexpr std::size_t k_zlib_block_bytes = 32768;  // vtkXMLWriter's default block size

/// VTK's zlib layout of `bytes`: header [blocks, block size, last partial block size or 0,
/// compressed size of each block] (UInt64), then the compressed blocks.
std::string zlib_blocks(std::string_view bytes) {
    const std::size_t n_blocks = (bytes.size() + k_zlib_block_bytes - 1) / k_zlib_block_bytes;
    std::vector<std::uint64_t> header{n_blocks, k_zlib_block_bytes,
                                      bytes.size() % k_zlib_block_bytes};
    const std::size_t header_bytes = (3 + n_blocks) * sizeof(std::uint64_t);
    std::string out(header_bytes + n_blocks * ::compressBound(k_zlib_block_bytes), '\0');
    std::size_t at = header_bytes;
    for (std::size_t b = 0; b < n_blocks; ++b) {
        const std::size_t begin = b * k_zlib_block_bytes;
        const std::size_t size = std::min(k_zlib_block_bytes, bytes.size() - begin);
        uLongf compressed = ::compressBound(size);
        if (::compress2(reinterpret_cast<Bytef*>(out.data() + at), &compressed,
                        reinterpret_cast<const Bytef*>(bytes.data() + begin), size,
                        k_zlib_level) != Z_OK) {
            throw std::runtime_error("zlib could not compress a frame array");
        }
        header.push_back(compressed);
        at += compressed;
    }
    out.resize(at);
    std::memcpy(out.data(), header.data(), header_bytes);
    return out;
}

/// The file as pieces: views into the frame and into buffers it owns (a deque: adding a buffer
/// moves none of the others, so the views stay valid).
class VtuPieces {
public:
    void view(std::string_view bytes) { pieces_.push_back(bytes); }
    void own(std::string bytes) {
        buffers_.push_back(std::move(bytes));
        pieces_.push_back(buffers_.back());
    }
    /// The text written so far into the buffer `text()` returns ends here as a piece.
    std::string& text() { return text_; }
    void end_text() {
        own(std::move(text_));
        text_.clear();
    }
    [[nodiscard]] const std::vector<std::string_view>& pieces() const { return pieces_; }

private:
    std::deque<std::string> buffers_;
    std::vector<std::string_view> pieces_;
    std::string text_;
};

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

/// The pieces of the .vtu file of `frame`; `offsets` and `types` hold the cells' arrays (their
/// storage must outlive the pieces, like the frame's).
VtuPieces vtu_pieces(const FieldFrame& frame, VtuFormat format, std::vector<std::int64_t>& offsets,
                     std::vector<std::uint8_t>& types) {
    if (format.compression == VtuCompression::Zlib && format.encoding != VtuEncoding::Raw) {
        throw std::invalid_argument("zlib compression of a .vtu file needs the raw encoding.");
    }
    const std::size_t n_points = frame.points.size();
    const std::size_t n_cells = frame.triangles.size();
    check_arrays(frame.point_data, n_points, "point data");
    check_arrays(frame.cell_data, n_cells, "cell data");
    for (std::size_t e = 0; e < n_cells; ++e) {
        for (const Index v : frame.triangles[e]) {
            if (v < 0 || static_cast<std::size_t>(v) >= n_points) {
                throw std::invalid_argument(fmt::format(
                    "triangle {} names point {}, but the frame has {} points.", e, v, n_points));
            }
        }
    }
    // the points and triangles are written straight from the frame's memory
    static_assert(sizeof(Vec3) == 3 * sizeof(Real) && sizeof(Index) == sizeof(std::int32_t) &&
                  sizeof(std::array<Index, 3>) == 3 * sizeof(Index));
    offsets.resize(n_cells);
    for (std::size_t e = 0; e < n_cells; ++e) offsets[e] = static_cast<std::int64_t>(3 * (e + 1));
    types.assign(n_cells, k_vtk_triangle);

    std::vector<Array> point_arrays, cell_arrays;
    for (const FieldArray& a : frame.point_data)
        point_arrays.push_back(
            {"Float64", a.name, a.components, bytes_of(a.values.data(), a.values.size())});
    for (const FieldArray& a : frame.cell_data)
        cell_arrays.push_back(
            {"Float64", a.name, a.components, bytes_of(a.values.data(), a.values.size())});
    const Array points{
        "Float64", "Points", 3,
        bytes_of(frame.points.empty() ? nullptr : frame.points[0].data(), 3 * n_points)};
    const std::array<Array, 3> cells{
        Array{"Int32", "connectivity", 0,
              bytes_of(frame.triangles.empty() ? nullptr : frame.triangles[0].data(), 3 * n_cells)},
        Array{"Int64", "offsets", 0, bytes_of(offsets.data(), n_cells)},
        Array{"UInt8", "types", 0, bytes_of(types.data(), n_cells)}};

    const bool appended = format.encoding == VtuEncoding::Raw;
    const bool zlib = format.compression == VtuCompression::Zlib;
    VtuPieces file;
    std::vector<std::string_view> appended_views;  // raw: the arrays' bytes, in order
    std::vector<std::string> compressed;           // zlib: the arrays' blocks, in order
    std::uint64_t appended_offset = 0;
    std::string& xml = file.text();
    std::size_t total_bytes = points.bytes.size();
    for (const auto* list : {&point_arrays, &cell_arrays})
        for (const Array& a : *list) total_bytes += a.bytes.size();
    for (const Array& a : cells) total_bytes += a.bytes.size();
    xml.reserve(4096 + (appended ? 0 : 2 * total_bytes));  // base64: 4/3; ascii: ~2.5 per byte

    auto data_array = [&](const Array& a) {
        fmt::format_to(std::back_inserter(xml), "        <DataArray type=\"{}\" Name=\"{}\"",
                       a.type, xml_escape(a.name));
        if (a.components > 0) {
            fmt::format_to(std::back_inserter(xml), " NumberOfComponents=\"{}\"", a.components);
        }
        if (appended) {
            fmt::format_to(std::back_inserter(xml), " format=\"appended\" offset=\"{}\"/>\n",
                           appended_offset);
            if (zlib) {
                compressed.push_back(zlib_blocks(a.bytes));
                appended_offset += compressed.back().size();
            } else {
                appended_views.push_back(a.bytes);
                appended_offset += sizeof(std::uint64_t) + a.bytes.size();
            }
            return;
        }
        const bool ascii = format.encoding == VtuEncoding::Ascii;
        fmt::format_to(std::back_inserter(xml), " format=\"{}\">\n", ascii ? "ascii" : "binary");
        if (ascii) {
            append_ascii(xml, a);
        } else {
            const std::string data = byte_count(a.bytes.size()).append(a.bytes);
            append_base64(xml, reinterpret_cast<const unsigned char*>(data.data()), data.size());
        }
        xml += "\n        </DataArray>\n";
    };

    fmt::format_to(std::back_inserter(xml),
                   "<?xml version=\"1.0\"?>\n"
                   "<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"{}\" "
                   "header_type=\"UInt64\"{}>\n"
                   "  <UnstructuredGrid>\n"
                   "    <FieldData>\n"
                   "      <DataArray type=\"Float64\" Name=\"TimeValue\" NumberOfTuples=\"1\" "
                   "format=\"ascii\">\n        {}\n      </DataArray>\n"
                   "    </FieldData>\n"
                   "    <Piece NumberOfPoints=\"{}\" NumberOfCells=\"{}\">\n",
                   byte_order_name(), zlib ? " compressor=\"vtkZLibDataCompressor\"" : "",
                   frame.time, n_points, n_cells);
    xml += "      <PointData>\n";
    for (const Array& a : point_arrays) data_array(a);
    xml += "      </PointData>\n      <CellData>\n";
    for (const Array& a : cell_arrays) data_array(a);
    xml += "      </CellData>\n      <Points>\n";
    data_array(points);
    xml += "      </Points>\n      <Cells>\n";
    for (const Array& a : cells) data_array(a);
    xml += "      </Cells>\n    </Piece>\n  </UnstructuredGrid>\n";
    if (!appended) {
        xml += "</VTKFile>\n";
        file.end_text();
        return file;
    }
    xml += "  <AppendedData encoding=\"raw\">\n   _";
    file.end_text();
    for (std::string& blocks : compressed) file.own(std::move(blocks));
    for (const std::string_view bytes : appended_views) {
        file.own(byte_count(bytes.size()));
        file.view(bytes);
    }
    file.text() = "\n  </AppendedData>\n</VTKFile>\n";
    file.end_text();
    return file;
}

}  // namespace

std::string vtu_text(const FieldFrame& frame, VtuFormat format) {
    std::vector<std::int64_t> offsets;
    std::vector<std::uint8_t> types;
    const VtuPieces file = vtu_pieces(frame, format, offsets, types);
    std::string out;
    std::size_t size = 0;
    for (const std::string_view piece : file.pieces()) size += piece.size();
    out.reserve(size);
    for (const std::string_view piece : file.pieces()) out += piece;
    return out;
}

void write_vtu(const std::filesystem::path& path, const FieldFrame& frame, VtuFormat format) {
    std::vector<std::int64_t> offsets;
    std::vector<std::uint8_t> types;
    const VtuPieces file = vtu_pieces(frame, format, offsets, types);
    write_file_atomic(path, file.pieces());
}

void write_pvtu(const std::filesystem::path& path, const FieldFrame& layout,
                const std::vector<std::string>& pieces) {
    std::string out;
    fmt::format_to(std::back_inserter(out),
                   "<?xml version=\"1.0\"?>\n"
                   "<VTKFile type=\"PUnstructuredGrid\" version=\"1.0\" byte_order=\"{}\" "
                   "header_type=\"UInt64\">\n"
                   "  <PUnstructuredGrid GhostLevel=\"0\">\n",
                   byte_order_name());
    const auto declare = [&out](const char* tag, const std::vector<FieldArray>& arrays) {
        fmt::format_to(std::back_inserter(out), "    <{}>\n", tag);
        for (const FieldArray& a : arrays)
            fmt::format_to(std::back_inserter(out),
                           "      <PDataArray type=\"Float64\" Name=\"{}\" "
                           "NumberOfComponents=\"{}\"/>\n",
                           xml_escape(a.name), a.components);
        fmt::format_to(std::back_inserter(out), "    </{}>\n", tag);
    };
    declare("PPointData", layout.point_data);
    declare("PCellData", layout.cell_data);
    out +=
        "    <PPoints>\n"
        "      <PDataArray type=\"Float64\" Name=\"Points\" NumberOfComponents=\"3\"/>\n"
        "    </PPoints>\n";
    for (const std::string& piece : pieces)
        fmt::format_to(std::back_inserter(out), "    <Piece Source=\"{}\"/>\n", xml_escape(piece));
    out += "  </PUnstructuredGrid>\n</VTKFile>\n";
    write_file_atomic(path, out);
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
