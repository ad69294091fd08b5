// Abaqus .inp shell-mesh reader (see abaqus_reader.hpp).
#include "fpmshell/mesh/abaqus_reader.hpp"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>

#include "fpmshell/core/errors.hpp"
#include "fpmshell/core/text.hpp"
#include "fpmshell/mesh/raw_mesh.hpp"

namespace fpmshell {
namespace {

using namespace text_mesh;

/// Number of nodes of a supported surface element type, 0 for a line element, -1 otherwise.
int element_nodes(const std::string& type) {
    static const std::vector<std::string> tri = {"S3",   "S3R",  "S3RS",  "CPS3",  "CPE3",
                                                 "M3D3", "R3D3", "STRI3", "SFM3D3"};
    static const std::vector<std::string> quad = {"S4",    "S4R",    "S4RS",   "S4R5", "CPS4",
                                                  "CPS4R", "CPE4",   "CPE4R",  "M3D4", "M3D4R",
                                                  "R3D4",  "SFM3D4", "SFM3D4R"};
    if (std::find(tri.begin(), tri.end(), type) != tri.end()) return 3;
    if (std::find(quad.begin(), quad.end(), type) != quad.end()) return 4;
    for (const char* prefix : {"T2D", "T3D", "B2", "B3", "PIPE", "MASS", "ROTARYI", "SPRING",
                               "DASHPOT", "CONN", "GAP", "RB2D", "RB3D"})
        if (type.rfind(prefix, 0) == 0) return 0;
    return -1;
}

struct Keyword {
    std::string name;                           ///< upper case, e.g. "ELEMENT"
    std::map<std::string, std::string> params;  ///< upper-case key -> value as written
};

Keyword parse_keyword(const std::string& line) {
    Keyword k;
    const auto fields = split_commas(line.substr(1));
    if (fields.empty()) return k;
    k.name = upper(fields[0]);
    for (std::size_t i = 1; i < fields.size(); ++i) {
        const auto eq = fields[i].find('=');
        std::string key = upper(trim(fields[i].substr(0, eq)));
        std::string value = eq == std::string::npos ? "" : trim(fields[i].substr(eq + 1));
        if (value.size() >= 2 && value.front() == '"' && value.back() == '"')
            value = value.substr(1, value.size() - 2);
        if (!key.empty()) k.params[key] = value;
    }
    return k;
}

enum class Block { Skip, Node, Element, NodeSet, ElementSet };

class AbaqusReader {
public:
    explicit AbaqusReader(const std::string& path) { raw_.path = path; }

    MeshData read() {
        std::ifstream in(raw_.path, std::ios::binary);
        if (!in) raw_.fail(0, "cannot open the mesh file");
        std::error_code size_error;
        raw_.file_bytes = std::filesystem::file_size(raw_.path, size_error);
        std::string text;
        int number = 0;
        std::string pending;  // an element card continued on the next line
        int pending_line = 0;
        while (std::getline(in, text)) {
            ++number;
            const std::string t = trim(text);
            if (t.empty() || t.rfind("**", 0) == 0) continue;
            if (t.front() == '*') {
                if (!pending.empty())
                    raw_.fail(pending_line,
                              "the element card ends with a comma "
                              "but is not continued");
                start(parse_keyword(t), number);
                continue;
            }
            if (block_ == Block::Element && t.back() == ',') {
                if (pending.empty()) pending_line = number;
                pending += t;
                continue;
            }
            if (!pending.empty()) {
                data(pending + t, pending_line);
                pending.clear();
            } else {
                data(t, number);
            }
        }
        if (!pending.empty()) data(pending, pending_line);
        return finish_raw_mesh(raw_);
    }

private:
    /// Canonical spelling of a set name (Abaqus names are case-insensitive).
    std::string canonical(const std::string& name, int line) {
        if (name.empty()) raw_.fail(line, "a set keyword needs a name (NSET=name or ELSET=name)");
        const auto [it, inserted] = names_.try_emplace(upper(name), name);
        if (inserted) raw_.set_lines[name] = line;
        return it->second;
    }

    void start(const Keyword& k, int line) {
        block_ = Block::Skip;
        generate_ = k.params.count("GENERATE") != 0;
        if (k.name == "INCLUDE")
            raw_.fail(line, "*INCLUDE is not supported; put the whole mesh in one file");
        if (k.name == "NODE") {
            block_ = Block::Node;
            set_ = k.params.count("NSET") ? canonical(k.params.at("NSET"), line) : "";
        } else if (k.name == "ELEMENT") {
            block_ = Block::Element;
            const auto type = k.params.find("TYPE");
            if (type == k.params.end())
                raw_.fail(line, "*ELEMENT needs a TYPE= parameter, e.g. TYPE=S3");
            type_ = upper(type->second);
            n_nodes_ = element_nodes(type_);
            if (n_nodes_ < 0)
                raw_.fail(line, "element type " + type_ +
                                    " is not supported; expected 3-node triangles (S3, S3R, "
                                    "CPS3, M3D3, ...) or 4-node quadrangles (S4, S4R, CPS4, ...)");
            set_ = k.params.count("ELSET") ? canonical(k.params.at("ELSET"), line) : "";
        } else if (k.name == "NSET") {
            if (k.params.count("ELSET"))
                raw_.fail(line, "*NSET with ELSET= is not supported; list the nodes instead");
            block_ = Block::NodeSet;
            set_ = canonical(k.params.count("NSET") ? k.params.at("NSET") : "", line);
            (void)raw_.node_sets[set_];
        } else if (k.name == "ELSET") {
            block_ = Block::ElementSet;
            set_ = canonical(k.params.count("ELSET") ? k.params.at("ELSET") : "", line);
            (void)raw_.element_sets[set_];
        }
    }

    long long id(const std::string& field, int line, const char* what) const {
        long long v = 0;
        if (!parse_id(field, v))
            raw_.fail(line, std::string("expected a ") + what + " number, got '" + field + "'");
        return v;
    }

    void data(const std::string& t, int line) {
        auto fields = split_commas(t);
        while (!fields.empty() && fields.back().empty()) fields.pop_back();
        switch (block_) {
            case Block::Skip:
                return;
            case Block::Node: {
                if (fields.size() < 3 || fields.size() > 4)
                    raw_.fail(line, "a *NODE line needs: node number, x, y[, z]");
                Vec3 x = Vec3::Zero();
                for (std::size_t k = 1; k < fields.size(); ++k)
                    if (!parse_real(fields[k], x[static_cast<Index>(k - 1)]))
                        raw_.fail(line, "coordinate '" + fields[k] + "' is not a finite number");
                const long long n = id(fields[0], line, "node");
                raw_.add_node(n, x, line);
                if (!set_.empty()) raw_.node_sets[set_].push_back(n);
                return;
            }
            case Block::Element: {
                const std::size_t expected = n_nodes_ == 0 ? 0 : static_cast<std::size_t>(n_nodes_);
                if (fields.size() < 2 || (expected > 0 && fields.size() != expected + 1))
                    raw_.fail(line, "an element of type " + type_ + " needs its number and " +
                                        std::to_string(expected) + " node numbers");
                const long long e = id(fields[0], line, "element");
                std::vector<long long> nodes;
                for (std::size_t k = 1; k < fields.size(); ++k)
                    nodes.push_back(id(fields[k], line, "node"));
                if (n_nodes_ == 0) {
                    if (!raw_.other_elements.try_emplace(e, nodes).second)
                        raw_.fail(line, "element " + std::to_string(e) + " is defined twice");
                } else {
                    raw_.add_shell(e, nodes, line);
                }
                if (!set_.empty()) raw_.element_sets[set_].push_back(e);
                return;
            }
            case Block::NodeSet:
            case Block::ElementSet: {
                auto& sets = block_ == Block::NodeSet ? raw_.node_sets : raw_.element_sets;
                auto& members = sets[set_];
                if (generate_) {
                    if (fields.size() < 2 || fields.size() > 3)
                        raw_.fail(line, "a GENERATE line needs: first, last[, increment]");
                    const long long first = id(fields[0], line, "first");
                    const long long last = id(fields[1], line, "last");
                    const long long step =
                        fields.size() == 3 ? id(fields[2], line, "increment") : 1;
                    if (step <= 0 || first < 0 || last < first)
                        raw_.fail(line, "GENERATE needs 0 <= first <= last and an increment >= 1");
                    const long long count = (last - first) / step + 1;
                    raw_.add_generated(count, line);
                    for (long long k = 0; k < count; ++k) members.push_back(first + k * step);
                    return;
                }
                for (const std::string& f : fields) {
                    if (f.empty()) continue;
                    long long v = 0;
                    if (parse_id(f, v)) {
                        members.push_back(v);
                        continue;
                    }
                    const auto other = names_.find(upper(f));
                    if (other == names_.end() || sets.count(other->second) == 0)
                        raw_.fail(line, "'" + f +
                                            "' is neither a number nor the name of a set "
                                            "defined above");
                    const auto copy = sets.at(other->second);
                    members.insert(members.end(), copy.begin(), copy.end());
                }
                return;
            }
        }
    }

    RawMesh raw_;
    Block block_ = Block::Skip;
    bool generate_ = false;
    std::string set_;
    std::string type_;
    int n_nodes_ = 0;
    std::map<std::string, std::string> names_;  ///< upper-case name -> spelling first used
};

}  // namespace

MeshData read_abaqus(const std::string& path) { return AbaqusReader(path).read(); }

}  // namespace fpmshell
