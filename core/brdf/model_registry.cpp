// The run-time view of the model list and dispatch of eval over packed values (see model_registry.h).
#include "brdf/model_registry.h"

#include <array>

#include "util/diagnostic.h"

namespace glint {
namespace {

const std::array<ModelInfo, Models::size>& infos() {
    static const auto table = [] {
        std::array<ModelInfo, Models::size> all;
        int index = 0;
        forEachModel(Models{}, [&]<class M>(M) {
            all[index] = describeModel<M>(static_cast<BrdfModel>(index));
            ++index;
        });
        return all;
    }();
    return table;
}

template <class M>
typename M::Params unpackChecked(std::span<const float> values) {
    GLINT_CHECK(static_cast<int>(values.size()) == packedSize(M::params));
    return unpack<M>(values.data());
}

}  // namespace

std::span<const ModelInfo> allModels() { return infos(); }

const ModelInfo& modelInfo(BrdfModel model) {
    GLINT_CHECK(static_cast<int>(model) >= 0 && static_cast<int>(model) < Models::size);
    return infos()[static_cast<int>(model)];
}

std::optional<BrdfModel> findModel(std::string_view id) {
    for (const ModelInfo& info : infos())
        if (id == info.id) return info.model;
    return std::nullopt;
}

glm::vec3 evalBrdf(BrdfModel model, std::span<const float> values, glm::vec3 wi, glm::vec3 wo,
                   const ShadingFrame& frame) {
    return dispatch(model, [&]<class M>(M) { return M::eval(unpackChecked<M>(values), wi, wo, frame); });
}

glm::vec3 ambientReflectance(BrdfModel model, std::span<const float> values, glm::vec3 wo, const ShadingFrame& frame) {
    return dispatch(model, [&]<class M>(M) {
        if constexpr (HasAmbient<M>) return M::ambientReflectance(unpackChecked<M>(values), wo, frame);
        else return glm::vec3(0.0f);
    });
}

bool isReciprocal(BrdfModel model, std::span<const float> values) {
    return dispatch(model, [&]<class M>(M) {
        if constexpr (HasFormReciprocity<M>) return M::isReciprocal(unpackChecked<M>(values));
        else return M::reciprocal;
    });
}

}  // namespace glint
