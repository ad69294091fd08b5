// Raw text-mesh data -> MeshData (see raw_mesh.hpp).
#include "fpmshell/mesh/raw_mesh.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <string_view>

#include "fpmshell/core/errors.hpp"
#include "fpmshell/core/text.hpp"

namespace fpmshell {

namespace text_mesh {

std::string upper(std::string s) {
    std::transform(s.begin(), s.end(), s.begin(),
                   [](unsigned char c) { return static_cast<char>(std::toupper(c)); });
    return s;
}

std::vector<std::string> split_commas(const std::string& s) {
    std::vector<std::string> out;
    if (trim(s).empty()) return out;
    std::size_t start = 0;
    while (true) {
        const auto comma = s.find(',', start);
        out.push_back(
            trim(s.substr(start, comma == std::string::npos ? std::string::npos : comma - start)));
        if (comma == std::string::npos) break;
        start = comma + 1;
    }
    return out;
}

std::vector<std::string> split_blanks(const std::string& s) {
    std::vector<std::string> out;
    std::size_t i = 0;
    while (i < s.size()) {
        while (i < s.size() && std::isspace(static_cast<unsigned char>(s[i]))) ++i;
        const std::size_t start = i;
        while (i < s.size() && !std::isspace(static_cast<unsigned char>(s[i]))) ++i;
        if (i > start) out.push_back(s.substr(start, i - start));
    }
    return out;
}

namespace {

/// The field without its leading and trailing blanks (no copy: the readers parse millions).
std::string_view trimmed(std::string_view f) {
    const auto blank = [](char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n'; };
    while (!f.empty() && blank(f.front())) f.remove_prefix(1);
    while (!f.empty() && blank(f.back())) f.remove_suffix(1);
    return f;
}

}  // namespace

bool parse_id(const std::string& field, long long& value) {
    const std::string_view f = trimmed(field);
    if (f.empty()) return false;
    const char* first = f.data() + (f.front() == '+' ? 1 : 0);
    const char* last = f.data() + f.size();
    const auto [ptr, ec] = std::from_chars(first, last, value);
    return ec == std::errc() && ptr == last;
}

bool parse_real(const std::string& field, Real& value) {
    const std::string_view view = trimmed(field);
    if (view.empty()) return false;
    // the common case, a plain decimal or E exponent, parsed in place
    const bool letters = view.find_first_of("dDeE") != std::string_view::npos;
    const bool inner_sign = view.find_first_of("+-", 1) != std::string_view::npos;
    std::string f;
    if (letters || inner_sign) {
        f.assign(view);
        for (char& c : f)
            if (c == 'd' || c == 'D') c = 'e';
        // Fortran's exponent without its letter, as fixed-column writers save a column: 2.00000-3
        if (f.find_first_of("eE") == std::string::npos)
            if (const auto sign = f.find_last_of("+-");
                sign != std::string::npos && sign > 0 &&
                (std::isdigit(static_cast<unsigned char>(f[sign - 1])) || f[sign - 1] == '.'))
                f.insert(sign, 1, 'e');
    }
    const std::string_view text = f.empty() ? view : std::string_view(f);
    const char* first = text.data() + (text.front() == '+' ? 1 : 0);
    const char* last = text.data() + text.size();
    const auto [ptr, ec] = std::from_chars(first, last, value, std::chars_format::general);
    return ec == std::errc() && ptr == last && std::isfinite(value);
}

bool parse_whole(const std::string& field, long long& value) {
    if (parse_id(field, value)) return true;
    Real r = 0;
    if (!parse_real(field, r) || r != std::round(r) || std::abs(r) >= 1e15) return false;
    value = static_cast<long long>(r);
    return true;
}

}  // namespace text_mesh

void RawMesh::fail(int line, const std::string& message) const {
    throw InputError(input_error_text(path, line, "", message));
}

std::pair<std::string, int> RawMesh::set_place(const std::string& name) const {
    const auto file = set_files.find(name);
    const auto line = set_lines.find(name);
    return {file == set_files.end() ? path : file->second,
            line == set_lines.end() ? 0 : line->second};
}

void RawMesh::fail_in_set(const std::string& name, const std::string& message) const {
    const auto [file, line] = set_place(name);
    throw InputError(input_error_text(file, line, "", message));
}

void RawMesh::add_generated(long long count, int line) {
    if (count > static_cast<long long>(file_bytes) - generated)
        fail(line, "the GENERATE ranges list more ids (" + std::to_string(generated + count) +
                       " so far) than a file of " + std::to_string(file_bytes) +
                       " bytes can define: every member must be a node or element of the file");
    generated += count;
}

void RawMesh::add_node(long long id, const Vec3& x, int line) {
    const auto [it, inserted] = nodes.try_emplace(id, Node{x, line});
    if (!inserted)
        fail(line, "node " + std::to_string(id) + " is defined twice (first at line " +
                       std::to_string(it->second.line) + "); node numbers must be unique");
}

void RawMesh::add_shell(long long id, std::vector<long long> node_ids, int line) {
    shells.push_back({id, std::move(node_ids), line});
}

MeshData finish_raw_mesh(const RawMesh& raw) {
    if (raw.shells.empty())
        raw.fail(0,
                 "the file holds no shell element (triangles or quadrangles); expected a "
                 "surface mesh");
    // Duplicate element ids.
    std::unordered_map<long long, std::size_t> shell_of_id;  // id -> index in raw.shells
    shell_of_id.reserve(raw.shells.size());
    for (std::size_t k = 0; k < raw.shells.size(); ++k) {
        const auto& e = raw.shells[k];
        const auto [it, inserted] = shell_of_id.try_emplace(e.id, k);
        if (!inserted || raw.other_elements.count(e.id) != 0)
            raw.fail(e.line, "element " + std::to_string(e.id) +
                                 " is defined twice; element numbers must be unique");
        for (const long long n : e.nodes)
            if (raw.nodes.count(n) == 0)
                raw.fail(e.line, "element " + std::to_string(e.id) + " refers to node " +
                                     std::to_string(n) + ", which the file does not define");
    }

    // Compact node numbering, in increasing id order, of the nodes used by shells and those
    // that carry a point mass (the file's own; any other is named where the mass is read).
    std::vector<long long> used;
    for (const auto& e : raw.shells) used.insert(used.end(), e.nodes.begin(), e.nodes.end());
    for (const long long n : raw.mass_nodes)
        if (raw.nodes.count(n) != 0) used.push_back(n);
    std::sort(used.begin(), used.end());
    used.erase(std::unique(used.begin(), used.end()), used.end());
    MeshData mesh;
    std::unordered_map<long long, Index> index_of;
    index_of.reserve(used.size());
    for (const long long id : used) {
        index_of[id] = static_cast<Index>(mesh.nodes.size());
        mesh.nodes.push_back(raw.nodes.at(id).x);
        mesh.node_tag.push_back(static_cast<std::int64_t>(id));
    }

    // Triangles; shell k gives the triangles first_triangle[k] .. first_triangle[k+1]-1.
    std::vector<Index> first_triangle;
    first_triangle.reserve(raw.shells.size() + 1);
    for (const auto& e : raw.shells) {
        first_triangle.push_back(static_cast<Index>(mesh.triangles.size()));
        const Index a = index_of.at(e.nodes[0]);
        const Index b = index_of.at(e.nodes[1]);
        const Index c = index_of.at(e.nodes[2]);
        if (e.nodes.size() == 3) {
            mesh.triangles.push_back({a, b, c});
        } else {
            const Index d = index_of.at(e.nodes[3]);
            const auto x = [&](Index i) { return mesh.nodes[static_cast<std::size_t>(i)]; };
            if ((x(c) - x(a)).squaredNorm() <= (x(d) - x(b)).squaredNorm()) {
                mesh.triangles.push_back({a, b, c});
                mesh.triangles.push_back({a, c, d});
            } else {
                mesh.triangles.push_back({a, b, d});
                mesh.triangles.push_back({b, c, d});
            }
        }
        while (mesh.element_tag.size() < mesh.triangles.size())
            mesh.element_tag.push_back(static_cast<std::int64_t>(e.id));
    }
    first_triangle.push_back(static_cast<Index>(mesh.triangles.size()));

    // A set's node that no shell uses and no point mass is on is not a particle: it is left out
    // of the set (noted: LS-DYNA keeps it as a node of no mass, which moves nothing here).
    auto add_nodes = [&](const std::string& name, const std::vector<long long>& ids,
                         std::vector<long long>* left_out) {
        auto& set = mesh.node_sets[name];
        for (const long long id : ids) {
            const auto it = index_of.find(id);
            if (it != index_of.end())
                set.push_back(it->second);
            else if (left_out)
                left_out->push_back(id);
        }
    };
    for (const auto& [name, ids] : raw.node_sets) {
        for (const long long id : ids)
            if (raw.nodes.count(id) == 0)
                raw.fail_in_set(name, "the node set '" + name + "' lists node " +
                                          std::to_string(id) + ", which the file does not define");
        std::vector<long long> left_out;
        add_nodes(name, ids, &left_out);
        std::sort(left_out.begin(), left_out.end());
        left_out.erase(std::unique(left_out.begin(), left_out.end()), left_out.end());
        if (left_out.empty()) continue;
        const auto [file, line] = raw.set_place(name);
        std::string listed;
        for (std::size_t k = 0; k < left_out.size() && k < 5; ++k)
            listed += (k ? ", " : "") + std::to_string(left_out[k]);
        if (left_out.size() > 5) listed += ", ...";
        mesh.notes.push_back(file + ":" + std::to_string(line) + ": the node set '" + name +
                             "' lists " + std::to_string(left_out.size()) + " node" +
                             (left_out.size() > 1 ? "s" : "") + " (" + listed +
                             ") on no shell and without a point mass: left out of the set (a "
                             "node of no mass moves nothing; give it *ELEMENT_MASS to keep it)");
    }
    for (const auto& [name, ids] : raw.element_sets) {
        auto& elements = mesh.element_sets[name];
        std::vector<long long> nodes;
        for (const long long id : ids) {
            if (const auto it = shell_of_id.find(id); it != shell_of_id.end()) {
                for (Index t = first_triangle[it->second]; t < first_triangle[it->second + 1]; ++t)
                    elements.push_back(t);
                const auto& e = raw.shells[it->second];
                nodes.insert(nodes.end(), e.nodes.begin(), e.nodes.end());
            } else if (const auto other = raw.other_elements.find(id);
                       other != raw.other_elements.end()) {
                nodes.insert(nodes.end(), other->second.begin(), other->second.end());
            } else {
                raw.fail_in_set(name, "the element set '" + name + "' lists element " +
                                          std::to_string(id) + ", which the file does not define");
            }
        }
        add_nodes(name, nodes, nullptr);
    }
    for (auto* sets : {&mesh.node_sets, &mesh.element_sets}) {
        for (auto it = sets->begin(); it != sets->end();) {
            auto& members = it->second;
            std::sort(members.begin(), members.end());
            members.erase(std::unique(members.begin(), members.end()), members.end());
            it = members.empty() ? sets->erase(it) : std::next(it);
        }
    }
    return mesh;
}

}  // namespace fpmshell
