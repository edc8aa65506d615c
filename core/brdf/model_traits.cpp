// Run-time queries of the models' trait hooks (see model_traits.h).
#include "brdf/model_traits.h"

namespace glint {

std::optional<DeltaLobeWeights> deltaLobeWeights(BrdfModel model, std::span<const float> values, float cosIncident) {
    return dispatch(model, [&]<class M>(M) -> std::optional<DeltaLobeWeights> {
        if constexpr (HasDeltaLobeWeights<M>) return M::deltaLobeWeights(unpack<M>(values.data()), cosIncident);
        else return std::nullopt;
    });
}

bool transmits(BrdfModel model, std::span<const float> values) {
    return dispatch(model, [&]<class M>(M) {
        if constexpr (MayTransmit<M>) return M::transmits(unpack<M>(values.data()));
        else return false;
    });
}

std::optional<TextbookForm> textbookForm(BrdfModel model, std::span<const float> values) {
    return dispatch(model, [&]<class M>(M) -> std::optional<TextbookForm> {
        if constexpr (HasTextbookForm<M>) return M::textbookForm(unpack<M>(values.data()));
        else return std::nullopt;
    });
}

}  // namespace glint
