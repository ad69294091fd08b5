// The self-contacts lose the faces of eroded elements (theory.md §7.6).
#include <algorithm>

#include "fpmshell/contact/contact_solver.hpp"

namespace fpmshell {

void ContactSolver::drop_faces(const std::vector<Index>& eroded, bool search_again) {
    if (eroded.empty()) return;
    std::vector<Index> sorted = eroded;
    std::sort(sorted.begin(), sorted.end());
    for (Definition& d : definitions_) {
        if (d.def.type != ContactType::Self) continue;
        std::vector<Index>& faces = d.def.elements;
        const std::size_t before = faces.size();
        std::erase_if(faces,
                      [&](Index e) { return std::binary_search(sorted.begin(), sorted.end(), e); });
        if (faces.size() == before || !search_again) continue;
        d.searched = false;  // the next step searches the faces left
        d.candidate_triangles.clear();
    }
}

}  // namespace fpmshell
