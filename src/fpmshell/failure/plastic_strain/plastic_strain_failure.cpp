#include "fpmshell/failure/plastic_strain/plastic_strain_failure.hpp"

#include "fpmshell/io/yaml_access.hpp"

namespace fpmshell {

namespace {

std::any read_plastic_strain(const YamlValue& v, const Material& /*material*/) {
    return v.positive();
}

std::unique_ptr<PointFailure> make_plastic_strain(const std::any& parameters,
                                                  const Material& /*material*/) {
    return std::make_unique<PlasticStrainFailure>(std::any_cast<Real>(parameters));
}

}  // namespace

FailureCriterion plastic_strain_criterion() {
    return {"plastic_strain", read_plastic_strain, make_plastic_strain};
}

void add_plastic_strain_failure(Material& m, Real strain) {
    m.failure.criteria.push_back({"plastic_strain", strain});
}

}  // namespace fpmshell
