// ParaView output: one VTK XML UnstructuredGrid file (.vtu) per frame and a .pvd collection that
// lists the frames with their times (model-format.md: fields.pvd + fields/frame_NNNNN.vtu).
//
// File layout written here (VTK XML format version 1.0, header_type UInt64):
//  - Points: Float64 x 3. Cells: connectivity Int32, offsets Int64 (end of each cell), types
//    UInt8 = 5 (VTK_TRIANGLE). Point and cell arrays: Float64 with NumberOfComponents.
//  - FieldData "TimeValue" (Float64, 1 tuple, ascii) holds the frame time, so a lone .vtu knows
//    it too.
//  - Encoding Raw (default): every DataArray is format="appended" with its offset into one
//    <AppendedData encoding="raw"> block after the XML: '_', then per array an 8-byte UInt64
//    byte count and the values as they lie in memory (byte order stated in byte_order). The
//    arrays are written from the frame's memory without a copy: a frame of 10^6 triangles is
//    ~150 MB and must not cost more than the steps between two frames. The file is not
//    well-formed XML (raw bytes), as VTK's own appended files.
//  - Compression Zlib (Raw only): each array's bytes cut into blocks of 32 768, each compressed
//    by zlib; the array starts with VTK's compression header (UInt64 number of blocks, block
//    size, size of the last block if partial or 0, then every block's compressed size) and
//    <VTKFile compressor="vtkZLibDataCompressor">, as vtkXMLWriter writes it.
//  - Encoding Base64: format="binary", base64 of [UInt64 byte count][values] inline: the file
//    stays well-formed XML. Encoding Ascii: format="ascii" values (shortest round-trip decimal
//    form): larger, slower, for debugging and diffing.
// A frame of a distributed run is a .pvtu file (PUnstructuredGrid, GhostLevel 0) that declares
// the arrays and lists one .vtu piece per rank, each piece a file as above.
// Every file is replaced atomically (io/atomic_file.hpp).
#pragma once

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "fpmshell/core/types.hpp"
#include "fpmshell/io/field_frame.hpp"

namespace fpmshell {

enum class VtuEncoding { Raw, Base64, Ascii };
enum class VtuCompression { None, Zlib };

/// How the arrays of a .vtu file are stored (output.fields_encoding, output.fields_compression).
struct VtuFormat {
    VtuFormat() = default;
    VtuFormat(VtuEncoding e, VtuCompression c = VtuCompression::None)  // NOLINT: implicit
        : encoding(e), compression(c) {}
    VtuEncoding encoding = VtuEncoding::Raw;
    VtuCompression compression = VtuCompression::None;  ///< Zlib needs encoding Raw
};

/// The bytes of the .vtu file for `frame`. Throws std::invalid_argument when an array's size is
/// not n * components, a triangle names a point that does not exist, or the format asks for
/// compression with another encoding than Raw.
[[nodiscard]] std::string vtu_text(const FieldFrame& frame, VtuFormat format = {});

/// Writes `frame` to `path` (atomically; the folder must exist). Throws std::invalid_argument
/// for an inconsistent frame (see vtu_text) and std::runtime_error when the file cannot be
/// written.
void write_vtu(const std::filesystem::path& path, const FieldFrame& frame, VtuFormat format = {});

/// Writes the .pvtu file (VTK XML PUnstructuredGrid) of a frame cut into pieces, one .vtu file
/// each (`pieces`: their paths relative to the folder of `path`): it declares the arrays of
/// `layout` (their names and components; every piece holds the same arrays) and lists the
/// pieces. Atomically; throws std::runtime_error when the file cannot be written.
void write_pvtu(const std::filesystem::path& path, const FieldFrame& layout,
                const std::vector<std::string>& pieces);

/// A ParaView time series (.pvd). Every add() rewrites the whole file atomically, so the file
/// on disk always lists exactly the frames written so far.
class PvdSeries {
public:
    /// Starts an empty series and writes it at once (replacing any older file at that path,
    /// whose frames would otherwise be listed with the new ones).
    explicit PvdSeries(std::filesystem::path pvd_path);

    /// Appends a frame. `relative_vtu_path` is relative to the folder of the .pvd file
    /// (for example "fields/frame_00003.vtu"). Throws std::runtime_error on a write failure.
    void add(Real time, const std::string& relative_vtu_path);

    [[nodiscard]] const std::filesystem::path& path() const { return pvd_path_; }
    [[nodiscard]] std::size_t size() const { return entries_.size(); }
    /// (time, relative path) of every frame, in the order added.
    [[nodiscard]] const std::vector<std::pair<Real, std::string>>& entries() const {
        return entries_;
    }

private:
    void write() const;

    std::filesystem::path pvd_path_;
    std::vector<std::pair<Real, std::string>> entries_;
};

}  // namespace fpmshell
