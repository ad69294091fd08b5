// Gmsh .msh reader (see gmsh_reader.hpp). Gmsh keeps global state, so every read initialises
// it, reads, copies what we need and finalises it again, also when an error is thrown.
// Gmsh 4.8 crashes (double free, segmentation fault) on some malformed files (about 1 in 150
// randomly damaged files when fuzzed), so the read runs in a child process whose result comes
// back through a pipe: a crash or a hang of Gmsh becomes an InputError instead. Some damaged
// files make Gmsh allocate gigabytes before it fails (7.6 GB for a 144-byte file): the child's
// memory is limited to what a mesh of the file's size can need.
#include "fpmshell/mesh/gmsh_reader.hpp"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <new>
#include <sstream>
#include <string>
#include <unordered_map>
#include <vector>

#include "fpmshell/core/errors.hpp"
#include "fpmshell/mesh/gmsh_library.hpp"

namespace fpmshell {
namespace {

/// Initialises Gmsh quietly for the lifetime of the object.
class GmshSession {
public:
    explicit GmshSession(const GmshLibrary& gmsh) : gmsh_(gmsh) {
        gmsh_.initialize();
        gmsh_.set_number_option("General.Terminal", 0);
        gmsh_.set_number_option("General.Verbosity", 0);
    }
    ~GmshSession() { gmsh_.finalize(); }
    GmshSession(const GmshSession&) = delete;
    GmshSession& operator=(const GmshSession&) = delete;

private:
    const GmshLibrary& gmsh_;
};

[[noreturn]] void fail(const std::string& path, const std::string& msg) {
    throw InputError(input_error_text(path, 0, "", msg));
}

/// Refuses a file that declares more nodes, elements or entity blocks than it has bytes, before
/// Gmsh allocates for them: the counts after "$Nodes" and "$Elements" (format 2: the count;
/// format 4: blocks, count, lowest and highest tag, as text or, in a binary file of format 4,
/// as four 8-byte integers). `in` is after the format line.
void check_declared_sizes(std::ifstream& in, const std::string& path, bool binary4,
                          std::uintmax_t file_bytes) {
    std::string line;
    while (std::getline(in, line)) {
        while (!line.empty() && (line.back() == '\r' || line.back() == ' ')) line.pop_back();
        if (line != "$Nodes" && line != "$Elements") continue;
        std::vector<unsigned long long> counts;
        if (binary4) {
            std::uint64_t header[4] = {};
            if (!in.read(reinterpret_cast<char*>(header), sizeof header)) return;
            counts.assign(header, header + 2);
        } else {
            std::string numbers;
            if (!std::getline(in, numbers)) return;
            std::istringstream values(numbers);
            for (std::string token; values >> token && counts.size() < 2;) {
                unsigned long long v = 0;
                const auto [end, error] =
                    std::from_chars(token.data(), token.data() + token.size(), v);
                if (error != std::errc() || end != token.data() + token.size()) break;
                counts.push_back(v);
            }
        }
        for (const unsigned long long n : counts)
            if (n > file_bytes)
                fail(path, "the file declares " + std::to_string(n) + " " +
                               (line == "$Nodes" ? "nodes" : "elements") +
                               " (or blocks of them) after " + line + ", more than its " +
                               std::to_string(file_bytes) + " bytes can hold");
    }
}

/// Refuses what Gmsh would not read as a mesh: Gmsh falls back to interpreting unknown content
/// as a .geo script, which can run for ever or call the shell, so only files that start like
/// a .msh file are handed to it.
void check_msh_header(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) fail(path, "cannot open the mesh file");
    std::string first;
    while (first.empty() && std::getline(in, first)) {
        while (!first.empty() && (first.back() == '\r' || first.back() == ' ')) first.pop_back();
    }
    if (first.rfind("$MeshFormat", 0) != 0)
        fail(path,
             "this is not a Gmsh mesh file (it does not start with $MeshFormat); "
             "expected a .msh file of format 2 or 4");
    std::string format;
    std::getline(in, format);
    std::istringstream fields(format);
    double version = 0;
    int file_type = 0, data_size = 0;
    fields >> version >> file_type >> data_size;
    std::error_code size_error;
    check_declared_sizes(in, path, version >= 4 && file_type == 1 && data_size == 8,
                         std::filesystem::file_size(path, size_error));
}

/// Reads the mesh with Gmsh in this process.
MeshData read_in_process(const std::string& path) {
    MeshData mesh;
    try {
        const GmshLibrary& gmsh = GmshLibrary::instance();
        GmshSession session(gmsh);
        gmsh.open(path);

        std::vector<std::size_t> node_tags;
        std::vector<double> coords;
        gmsh.get_nodes(node_tags, coords);
        std::unordered_map<std::size_t, std::size_t> position_of_tag;  // tag -> index in coords
        position_of_tag.reserve(node_tags.size());
        for (std::size_t k = 0; k < node_tags.size(); ++k) position_of_tag[node_tags[k]] = k;

        // Surface elements. element_triangles maps a Gmsh element tag to its triangles.
        std::vector<int> types;
        std::vector<std::vector<std::size_t>> element_tags;
        std::vector<std::vector<std::size_t>> element_nodes;
        gmsh.get_elements(types, element_tags, element_nodes, 2, -1);
        std::vector<std::array<std::size_t, 3>> tagged_triangles;  // Gmsh node tags
        std::unordered_map<std::size_t, std::vector<Index>> element_triangles;
        auto coord = [&](std::size_t tag) {
            const auto it = position_of_tag.find(tag);
            if (it == position_of_tag.end())
                fail(path, "an element refers to node " + std::to_string(tag) +
                               ", which the file does not define");
            const std::size_t k = it->second;
            return Vec3(coords[3 * k], coords[3 * k + 1], coords[3 * k + 2]);
        };
        auto add = [&](std::size_t element, std::array<std::size_t, 3> t) {
            element_triangles[element].push_back(static_cast<Index>(tagged_triangles.size()));
            tagged_triangles.push_back(t);
            mesh.element_tag.push_back(static_cast<std::int64_t>(element));
        };
        for (std::size_t g = 0; g < types.size(); ++g) {
            const int type = types[g];
            const auto& tags = element_tags[g];
            const auto& nodes = element_nodes[g];
            if (type == 2) {
                for (std::size_t e = 0; e < tags.size(); ++e)
                    add(tags[e], {nodes[3 * e], nodes[3 * e + 1], nodes[3 * e + 2]});
            } else if (type == 3) {
                for (std::size_t e = 0; e < tags.size(); ++e) {
                    const std::size_t a = nodes[4 * e];
                    const std::size_t b = nodes[4 * e + 1];
                    const std::size_t c = nodes[4 * e + 2];
                    const std::size_t d = nodes[4 * e + 3];
                    // Split along the shorter diagonal; both halves keep the quad's orientation.
                    if ((coord(c) - coord(a)).squaredNorm() <=
                        (coord(d) - coord(b)).squaredNorm()) {
                        add(tags[e], {a, b, c});
                        add(tags[e], {a, c, d});
                    } else {
                        add(tags[e], {a, b, d});
                        add(tags[e], {b, c, d});
                    }
                }
            } else {
                fail(path, "surface elements of Gmsh type " + std::to_string(type) + " (" +
                               gmsh.element_type_name(type) +
                               ") are not supported; expected 3-node triangles or 4-node "
                               "quadrangles (set Mesh.ElementOrder = 1)");
            }
        }
        if (tagged_triangles.empty())
            fail(path,
                 "the file holds no triangle or quadrangle elements; expected a surface "
                 "mesh (an empty or truncated file, or a mesh of lines or volumes only?)");

        // Compact renumbering in increasing tag order of the nodes used by surface elements.
        std::vector<std::size_t> used;
        used.reserve(3 * tagged_triangles.size());
        for (const auto& t : tagged_triangles) used.insert(used.end(), t.begin(), t.end());
        std::sort(used.begin(), used.end());
        used.erase(std::unique(used.begin(), used.end()), used.end());
        std::unordered_map<std::size_t, Index> index_of_tag;
        index_of_tag.reserve(used.size());
        mesh.nodes.reserve(used.size());
        for (const std::size_t tag : used) {
            index_of_tag[tag] = static_cast<Index>(mesh.nodes.size());
            mesh.nodes.push_back(coord(tag));
        }
        mesh.triangles.reserve(tagged_triangles.size());
        for (const auto& t : tagged_triangles)
            mesh.triangles.push_back({index_of_tag[t[0]], index_of_tag[t[1]], index_of_tag[t[2]]});

        // Physical groups.
        for (const auto& [dim, tag] : gmsh.physical_groups()) {
            if (dim > 2) continue;
            std::string name = gmsh.physical_name(dim, tag);
            if (name.empty()) name = "physical_" + std::to_string(tag);
            std::vector<Index> node_set;
            if (dim == 2) {
                std::vector<Index> element_set;
                for (const int entity : gmsh.entities_for_physical_group(dim, tag)) {
                    std::vector<int> etypes;
                    std::vector<std::vector<std::size_t>> etags;
                    std::vector<std::vector<std::size_t>> enodes;
                    gmsh.get_elements(etypes, etags, enodes, 2, entity);
                    for (const auto& list : etags)
                        for (const std::size_t e : list) {
                            const auto it = element_triangles.find(e);
                            if (it == element_triangles.end()) continue;
                            element_set.insert(element_set.end(), it->second.begin(),
                                               it->second.end());
                        }
                }
                for (const Index t : element_set)
                    for (const Index v : mesh.triangles[static_cast<std::size_t>(t)])
                        node_set.push_back(v);
                std::sort(element_set.begin(), element_set.end());
                element_set.erase(std::unique(element_set.begin(), element_set.end()),
                                  element_set.end());
                if (!element_set.empty()) {
                    auto& es = mesh.element_sets[name];
                    es.insert(es.end(), element_set.begin(), element_set.end());
                    std::sort(es.begin(), es.end());
                    es.erase(std::unique(es.begin(), es.end()), es.end());
                }
            } else {
                for (const std::size_t t : gmsh.nodes_for_physical_group(dim, tag)) {
                    const auto it = index_of_tag.find(t);
                    if (it != index_of_tag.end()) node_set.push_back(it->second);
                }
            }
            if (node_set.empty()) continue;
            auto& ns = mesh.node_sets[name];
            ns.insert(ns.end(), node_set.begin(), node_set.end());
            std::sort(ns.begin(), ns.end());
            ns.erase(std::unique(ns.begin(), ns.end()), ns.end());
        }
    } catch (const InputError&) {
        throw;
    } catch (const std::exception& e) {
        fail(path, std::string("Gmsh cannot read the mesh (") + e.what() + ")");
    } catch (...) {
        fail(path, "Gmsh cannot read the mesh");
    }
    return mesh;
}

// ---- transport of a MeshData from the child process ----

template <typename T>
void put(std::string& out, const T& value) {
    out.append(reinterpret_cast<const char*>(&value), sizeof value);
}

template <typename T>
void put_vector(std::string& out, const std::vector<T>& v) {
    put(out, static_cast<std::uint64_t>(v.size()));
    out.append(reinterpret_cast<const char*>(v.data()), v.size() * sizeof(T));
}

void put_sets(std::string& out, const std::map<std::string, std::vector<Index>>& sets) {
    put(out, static_cast<std::uint64_t>(sets.size()));
    for (const auto& [name, members] : sets) {
        put(out, static_cast<std::uint64_t>(name.size()));
        out += name;
        put_vector(out, members);
    }
}

std::string serialize(const MeshData& m) {
    std::string out;
    put_vector(out, m.nodes);
    put_vector(out, m.triangles);
    put_vector(out, m.element_tag);
    put_sets(out, m.node_sets);
    put_sets(out, m.element_sets);
    return out;
}

/// Reads back what serialize wrote; false when the data is cut short.
class Reader {
public:
    explicit Reader(const std::string& data) : data_(data) {}
    template <typename T>
    bool get(T& value) {
        if (data_.size() - pos_ < sizeof value) return false;
        std::memcpy(&value, data_.data() + pos_, sizeof value);
        pos_ += sizeof value;
        return true;
    }
    template <typename T>
    bool get_vector(std::vector<T>& v) {
        std::uint64_t n = 0;
        if (!get(n) || n > (data_.size() - pos_) / sizeof(T)) return false;
        v.resize(static_cast<std::size_t>(n));
        std::memcpy(static_cast<void*>(v.data()), data_.data() + pos_, v.size() * sizeof(T));
        pos_ += v.size() * sizeof(T);
        return true;
    }
    bool get_sets(std::map<std::string, std::vector<Index>>& sets) {
        std::uint64_t count = 0;
        if (!get(count)) return false;
        for (std::uint64_t k = 0; k < count; ++k) {
            std::uint64_t length = 0;
            if (!get(length) || length > data_.size() - pos_) return false;
            std::string name = data_.substr(pos_, static_cast<std::size_t>(length));
            pos_ += static_cast<std::size_t>(length);
            if (!get_vector(sets[name])) return false;
        }
        return true;
    }
    [[nodiscard]] bool at_end() const { return pos_ == data_.size(); }

private:
    const std::string& data_;
    std::size_t pos_ = 0;
};

bool deserialize(const std::string& data, MeshData& m) {
    Reader r(data);
    return r.get_vector(m.nodes) && r.get_vector(m.triangles) && r.get_vector(m.element_tag) &&
           r.get_sets(m.node_sets) && r.get_sets(m.element_sets) && r.at_end();
}

/// The private writable memory this process has mapped (VmData of /proc/self/status), in
/// bytes; 0 when it cannot be read.
std::uint64_t mapped_data_bytes() {
    std::ifstream status("/proc/self/status");
    for (std::string line; std::getline(status, line);)
        if (line.rfind("VmData:", 0) == 0) {
            std::istringstream value(line.substr(7));
            std::uint64_t kb = 0;
            value >> kb;
            return kb * 1024;
        }
    return 0;
}

/// The memory Gmsh may take to read a file of `file_bytes` bytes: its start-up (the library's
/// data and initialisation: under 8 MB) and a multiple of the file's size. Meshes of 5.7 to
/// 78 MB (formats 2 and 4, ASCII and binary) took 7 to 18 bytes of memory per byte of file, the
/// most in ASCII with short numbers: a real mesh stays well inside, while a damaged file whose
/// counts make Gmsh allocate gigabytes is stopped at once (docs/model-format.md, `file:`).
std::uint64_t gmsh_memory_budget(std::uintmax_t file_bytes) {
    constexpr std::uint64_t k_start_up = std::uint64_t{256} << 20;
    constexpr std::uint64_t k_per_file_byte = 64;
    return k_start_up + k_per_file_byte * static_cast<std::uint64_t>(file_bytes);
}

/// Set in the child when an allocation failed (Gmsh's C API turns the exception into a plain
/// "failed", so the reason is kept here).
bool g_allocation_failed = false;

void on_allocation_failure() {
    g_allocation_failed = true;
    throw std::bad_alloc();
}

/// Lets the child map at most `budget` bytes more of private writable memory (RLIMIT_DATA,
/// which since Linux 4.7 covers mmap as well as the heap: Gmsh's and the C library's
/// allocations). The limit is set above what the process already has, since that (the
/// libraries' data, a sanitizer's shadow memory) counts too; it only ever lowers the limit.
void limit_memory(std::uint64_t budget) {
    const std::uint64_t now = mapped_data_bytes();
    rlimit limit{};
    if (now == 0 || ::getrlimit(RLIMIT_DATA, &limit) != 0) return;
    const rlim_t wanted = static_cast<rlim_t>(now + budget);
    if (limit.rlim_cur != RLIM_INFINITY && limit.rlim_cur <= wanted) return;
    limit.rlim_cur = wanted;
    ::setrlimit(RLIMIT_DATA, &limit);
}

/// Child side: read, send 'M' + mesh or 'E' + message, exit without running destructors.
[[noreturn]] void child(const std::string& path, std::uintmax_t file_bytes, int fd) {
    const int null_fd = ::open("/dev/null", O_WRONLY);
    if (null_fd >= 0) {  // Gmsh and the C library may print on crashes; keep the terminal clean
        ::dup2(null_fd, STDOUT_FILENO);
        ::dup2(null_fd, STDERR_FILENO);
    }
    const std::uint64_t budget = gmsh_memory_budget(file_bytes);
    limit_memory(budget);
    std::set_new_handler(on_allocation_failure);
    std::string out;
    try {
        out = "M" + serialize(read_in_process(path));
    } catch (const InputError& e) {
        out = std::string("E") + e.what();
    } catch (const std::exception& e) {
        out = std::string("E") +
              input_error_text(path, 0, "", std::string("cannot read the mesh (") + e.what() + ")");
    } catch (...) {
        out = "E" + input_error_text(path, 0, "", "cannot read the mesh");
    }
    if (g_allocation_failed && out.front() == 'E')
        out = "E" + input_error_text(path, 0, "",
                                     "Gmsh needed more than " + std::to_string(budget >> 20) +
                                         " MB of memory to read this file of " +
                                         std::to_string(file_bytes) +
                                         " bytes, far more than a mesh of its size takes; the "
                                         "file is probably damaged");
    const char* p = out.data();
    std::size_t left = out.size();
    while (left > 0) {
        const ssize_t n = ::write(fd, p, left);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) ::_exit(3);
        p += n;
        left -= static_cast<std::size_t>(n);
    }
    ::_exit(0);
}

}  // namespace

MeshData read_gmsh(const std::string& path, std::chrono::seconds time_limit) {
    check_msh_header(path);
    int fds[2];
    if (::pipe(fds) != 0) return read_in_process(path);  // no isolation possible: read here
    const pid_t pid = ::fork();
    if (pid < 0) {
        ::close(fds[0]);
        ::close(fds[1]);
        return read_in_process(path);
    }
    if (pid == 0) {
        ::close(fds[0]);
        std::error_code size_error;
        const std::uintmax_t file_bytes = std::filesystem::file_size(path, size_error);
        child(path, size_error ? 0 : file_bytes, fds[1]);
    }
    ::close(fds[1]);

    std::string data;
    bool timed_out = false;
    const auto deadline = std::chrono::steady_clock::now() + time_limit;
    char buffer[1 << 16];
    while (true) {
        const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(
            deadline - std::chrono::steady_clock::now());
        if (left.count() <= 0) {
            timed_out = true;
            break;
        }
        pollfd pfd{fds[0], POLLIN, 0};
        const int ready =
            ::poll(&pfd, 1, static_cast<int>(std::min<long long>(left.count(), 1000)));
        if (ready < 0 && errno != EINTR) break;
        if (ready <= 0) continue;
        const ssize_t n = ::read(fds[0], buffer, sizeof buffer);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) break;  // end of data (or a read error)
        data.append(buffer, static_cast<std::size_t>(n));
    }
    ::close(fds[0]);
    if (timed_out) ::kill(pid, SIGKILL);
    int status = 0;
    while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
    }
    if (timed_out)
        fail(path, "Gmsh did not finish reading the file within " +
                       std::to_string(time_limit.count()) + " s; the file is probably corrupt");
    if (WIFSIGNALED(status))
        fail(path, "Gmsh crashed while reading the file (signal " +
                       std::to_string(WTERMSIG(status)) +
                       "); the file is probably corrupt, check it by opening it in Gmsh");
    if (!data.empty() && data.front() == 'E') throw InputError(data.substr(1));
    MeshData mesh;
    if (data.empty() || data.front() != 'M' || !deserialize(data.substr(1), mesh))
        fail(path, "reading the file with Gmsh failed unexpectedly");
    return mesh;
}

}  // namespace fpmshell
