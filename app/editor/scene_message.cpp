// Messages that the next change of the scene drops (see scene_message.h).
#include "editor/scene_message.h"

namespace glint {

void SceneMessage::expire(std::uint64_t revision) {
    if (written_ || text_ != seen_) {
        revision_ = revision;
    } else if (revision != revision_) {
        text_.clear();
    }
    written_ = false;
    seen_ = text_;
}

}  // namespace glint
