// Binary restart file of a dynamic run (docs/running.md "Long runs: restart files"; LS-DYNA's
// d3dump, OpenRadioss' RST file): the complete state of the solver and of the result writers, byte
// for byte, so that a resumed run continues exactly (bitwise) as if it had never stopped.
//
// The layout is the host's (little-endian doubles on every machine we build for): a magic word
// and a format version, then named sections of raw values. A restart file is meant to be read
// back by the same build on the same machine, like LS-DYNA's; the version and section names
// turn any mismatch into one clear sentence instead of a garbled state.
//
// One function lists the members of a type for both directions: `transfer(archive, object)`
// calls `archive(member, member, ...)`; the writer reads the members, the reader fills them.
// Likewise one function, transfer_value, lays out the values themselves for both directions.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <array>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <memory>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <vector>

namespace fpmshell {

namespace restart_detail {
template <class T>
struct is_vector : std::false_type {};
template <class T, class A>
struct is_vector<std::vector<T, A>> : std::true_type {};
template <class T>
struct is_std_array : std::false_type {};
template <class T, std::size_t N>
struct is_std_array<std::array<T, N>> : std::true_type {};
template <class T>
struct is_pair : std::false_type {};
template <class A, class B>
struct is_pair<std::pair<A, B>> : std::true_type {};
template <class T>
struct fixed_eigen : std::false_type {};
template <class S, int R, int C, int O, int MR, int MC>
struct fixed_eigen<Eigen::Matrix<S, R, C, O, MR, MC>>
    : std::bool_constant<R != Eigen::Dynamic && C != Eigen::Dynamic> {};
template <class T>
constexpr bool is_fixed_eigen = fixed_eigen<T>::value;
template <class T>
constexpr bool is_raw = std::is_arithmetic_v<T> || std::is_enum_v<T>;
template <class T>
struct is_quaternion : std::false_type {};
template <class S, int O>
struct is_quaternion<Eigen::Quaternion<S, O>> : std::true_type {};

/// The fewest bytes one item of type T takes in a file: a stored length of n items is refused
/// when n times this exceeds the bytes left, so that a damaged length cannot ask for more memory
/// than a few times the file's size.
template <class T>
constexpr std::size_t least_stored_bytes() {
    if constexpr (is_raw<T>) {
        return sizeof(T);
    } else if constexpr (is_fixed_eigen<T>) {
        return sizeof(typename T::Scalar) * static_cast<std::size_t>(T::SizeAtCompileTime);
    } else if constexpr (is_quaternion<T>::value) {
        return 4 * sizeof(typename T::Scalar);
    } else if constexpr (std::is_same_v<T, std::string> || is_vector<T>::value) {
        return sizeof(std::uint64_t);  // the length
    } else if constexpr (is_std_array<T>::value) {
        return std::tuple_size_v<T> * least_stored_bytes<typename T::value_type>();
    } else if constexpr (is_pair<T>::value) {
        return least_stored_bytes<typename T::first_type>() +
               least_stored_bytes<typename T::second_type>();
    } else {
        return 1;
    }
}
}  // namespace restart_detail

template <class Archive, class T>
void transfer_value(Archive& archive, T& v);

/// Name of the restart file inside a result folder.
inline constexpr const char* k_restart_file = "restart.bin";

class RestartWriter {
public:
    RestartWriter();

    /// Writes every value in order.
    template <class... T>
    void operator()(const T&... values) {
        (put(values), ...);
    }
    /// Marks the start of a named section (checked when reading).
    void section(std::string_view name) { put(std::string(name)); }
    /// Writes `items` as operator() writes a std::vector of them (its length, then its items'
    /// bytes), keeping the vector instead of copying it into the file's bytes: a large block (a
    /// distributed run's restart piece, the elements' points) is written from its own memory.
    template <class T>
    requires restart_detail::is_raw<T>
    void put_block(std::vector<T> items) {
        put(static_cast<std::uint64_t>(items.size()));
        auto owner = std::make_shared<const std::vector<T>>(std::move(items));
        const std::string_view view(reinterpret_cast<const char*>(owner->data()),
                                    owner->size() * sizeof(T));
        block_bytes_ += view.size();
        blocks_.push_back({bytes_.size(), std::move(owner), view});
    }
    /// Writes the file atomically (write_file_atomic). Throws std::runtime_error on failure.
    void save(const std::filesystem::path& path) const;
    [[nodiscard]] std::size_t size() const { return bytes_.size() + block_bytes_; }
    /// The file whose content (magic word and sections) is `content`: the content and its
    /// checksum (for tools and tests that make restart files of their own).
    [[nodiscard]] static std::string with_checksum(std::string_view content);

private:
    void raw(const void* data, std::size_t n) { bytes_.append(static_cast<const char*>(data), n); }
    void flag(bool v) { bytes_.push_back(v ? '\1' : '\0'); }

    template <class Archive, class T>
    friend void transfer_value(Archive& archive, T& value);
    template <class T>
    void put(const T& v) {
        transfer_value(*this, const_cast<T&>(v));  // the writer only reads the value
    }
    /// Stores the length of a string or vector before its items.
    template <class Sequence>
    void transfer_length(const Sequence& v) {
        put(static_cast<std::uint64_t>(v.size()));
    }

    std::string bytes_;
    /// put_block's vectors, each with the place in bytes_ at which it stands
    struct Block {
        std::size_t place = 0;
        std::shared_ptr<const void> owner;  ///< the vector
        std::string_view bytes;             ///< its items
    };
    std::vector<Block> blocks_;
    std::size_t block_bytes_ = 0;
};

class RestartReader {
public:
    /// Reads the whole file and checks its magic word and format version. Throws InputError
    /// (one sentence naming the file) when it is missing, unreadable or not a restart file of
    /// this format.
    explicit RestartReader(const std::filesystem::path& path);

    /// Reads every value in order; a vector takes the stored length.
    template <class... T>
    void operator()(T&... values) {
        (get(values), ...);
    }
    /// Checks that the next section is `name` (InputError otherwise).
    void section(std::string_view name);
    /// Checks that every byte has been read (InputError otherwise).
    void finish() const;
    /// Throws InputError "<file>: <message>" (for checks of the content by the caller).
    [[noreturn]] void fail(const std::string& message) const;
    /// The file read.
    [[nodiscard]] const std::filesystem::path& path() const { return path_; }
    /// Format version of the file: the one this build writes (io/restart_archive.cpp), since
    /// the constructor refuses any other.
    [[nodiscard]] std::uint32_t format() const { return format_; }

private:
    void raw(void* data, std::size_t n);
    /// A bool: a byte 0 or 1 (another value fails as a corrupt file).
    void flag(bool& v);

    template <class Archive, class T>
    friend void transfer_value(Archive& archive, T& value);
    template <class T>
    void get(T& v) {
        transfer_value(*this, v);
    }
    /// Reads the length of a string or vector and gives it that many items.
    template <class Sequence>
    void transfer_length(Sequence& v) {
        v.resize(length(restart_detail::least_stored_bytes<typename Sequence::value_type>()));
    }
    /// A stored length of items of at least `item_bytes` bytes each, checked against the bytes
    /// left (a corrupt length fails cleanly, before anything is allocated).
    std::size_t length(std::size_t item_bytes);

    std::filesystem::path path_;
    std::string bytes_;
    std::size_t pos_ = 0;
    std::string section_ = "header";
    std::uint32_t format_ = 0;
};

/// The lengths of the strings and vectors of values, in the order transfer_value lays them out:
/// where the model fixes them (one entry per particle, per element), a loaded state must have
/// the lengths that a state built for the model has.
class LengthRecorder {
public:
    template <class... T>
    void operator()(const T&... values) {
        (transfer_value(*this, const_cast<T&>(values)), ...);  // only the lengths are read
    }
    void section(std::string_view /*name*/) {}
    void raw(const void* /*data*/, std::size_t /*n*/) {}
    void flag(bool /*v*/) {}
    template <class Sequence>
    void transfer_length(const Sequence& v) {
        lengths.push_back(v.size());
    }
    std::vector<std::size_t> lengths;
};

/// LengthRecorder's lengths of `values`.
template <class... T>
[[nodiscard]] std::vector<std::size_t> stored_lengths(const T&... values) {
    LengthRecorder r;
    r(values...);
    return r.lengths;
}

/// The bytes of one value, in the same order for both directions: a RestartWriter stores them,
/// a RestartReader fills the value. Raw values and fixed-size Eigen matrices are copied as they
/// are in memory; a string or a vector is its length and then its items; any other type is the
/// list of its members that its `transfer(archive, object)` gives.
template <class Archive, class T>
void transfer_value(Archive& archive, T& v) {
    using namespace restart_detail;
    if constexpr (std::is_same_v<T, bool>) {
        archive.flag(v);  // one byte, 0 or 1: any other byte is not a bool
    } else if constexpr (is_raw<T>) {
        archive.raw(&v, sizeof(T));
    } else if constexpr (is_fixed_eigen<T>) {
        archive.raw(v.data(),
                    sizeof(typename T::Scalar) * static_cast<std::size_t>(T::SizeAtCompileTime));
    } else if constexpr (is_quaternion<T>::value) {
        transfer_value(archive, v.coeffs());
    } else if constexpr (std::is_same_v<T, std::string>) {
        archive.transfer_length(v);
        archive.raw(v.data(), v.size());
    } else if constexpr (is_vector<T>::value) {
        archive.transfer_length(v);
        if constexpr (is_raw<typename T::value_type>) {
            archive.raw(v.data(), v.size() * sizeof(typename T::value_type));
        } else {
            for (auto& item : v) transfer_value(archive, item);
        }
    } else if constexpr (is_std_array<T>::value) {
        for (auto& item : v) transfer_value(archive, item);
    } else if constexpr (is_pair<T>::value) {
        transfer_value(archive, v.first);
        transfer_value(archive, v.second);
    } else {
        transfer(archive, v);
    }
}

}  // namespace fpmshell
