// Binary restart file of a dynamic run (README "Long runs: restart files"; LS-DYNA's d3dump,
// OpenRadioss' RST file): the complete state of the solver and of the result writers, byte for
// byte, so that a resumed run continues exactly (bitwise) as if it had never stopped.
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
    /// Writes the file atomically (write_file_atomic). Throws std::runtime_error on failure.
    void save(const std::filesystem::path& path) const;
    [[nodiscard]] std::size_t size() const { return bytes_.size(); }

private:
    void raw(const void* data, std::size_t n) { bytes_.append(static_cast<const char*>(data), n); }

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
    /// Format version of the file: the one this build writes (io/restart_archive.cpp), since
    /// the constructor refuses any other.
    [[nodiscard]] std::uint32_t format() const { return format_; }

private:
    void raw(void* data, std::size_t n);

    template <class Archive, class T>
    friend void transfer_value(Archive& archive, T& value);
    template <class T>
    void get(T& v) {
        transfer_value(*this, v);
    }
    /// Reads the length of a string or vector and gives it that many items.
    template <class Sequence>
    void transfer_length(Sequence& v) {
        v.resize(length());
    }
    /// A stored length, checked against the bytes left (a corrupt length fails cleanly).
    std::size_t length();

    std::filesystem::path path_;
    std::string bytes_;
    std::size_t pos_ = 0;
    std::string section_ = "header";
    std::uint32_t format_ = 0;
};

/// The bytes of one value, in the same order for both directions: a RestartWriter stores them,
/// a RestartReader fills the value. Raw values and fixed-size Eigen matrices are copied as they
/// are in memory; a string or a vector is its length and then its items; any other type is the
/// list of its members that its `transfer(archive, object)` gives.
template <class Archive, class T>
void transfer_value(Archive& archive, T& v) {
    using namespace restart_detail;
    if constexpr (is_raw<T>) {
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
