// SceneMessage: one line the editor shows about the scene as it is (a refused value and why,
// "Undone", "Saved …"). It stops being true when the scene changes after it was written (an
// edit, an undo or redo, a new or opened scene), and then it is dropped: the frame loop calls
// expire() once a frame with EditSession::revision(). It draws nothing.
#pragma once

#include <cstdint>
#include <string>
#include <utility>

namespace glint {

class SceneMessage {
public:
    SceneMessage& operator=(std::string text) {
        text_ = std::move(text);
        written_ = true;
        return *this;
    }
    SceneMessage& operator+=(const std::string& more) {
        text_ += more;
        written_ = true;
        return *this;
    }
    // For widgets that write a refusal into a string: a changed text counts as written.
    std::string& text() { return text_; }
    const std::string& text() const { return text_; }
    bool empty() const { return text_.empty(); }
    const char* c_str() const { return text_.c_str(); }
    void clear() { *this = std::string(); }

    // Once a frame, after everything that may write the message: a message written this frame
    // belongs to the scene at `revision`; an older one is dropped once the scene moved on.
    void expire(std::uint64_t revision);

private:
    std::string text_;
    std::string seen_;      // the text at the last expire()
    bool written_ = false;  // assigned since the last expire()
    std::uint64_t revision_ = 0;
};

}  // namespace glint
