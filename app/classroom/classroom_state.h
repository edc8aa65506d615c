// ClassroomState: what classroom mode keeps between frames in the editor — the lesson list and
// the lesson on screen, and the spectral render window's image. Presentation mode itself is a
// persisted setting (editor/settings.h). It holds no GL objects and draws nothing.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "classroom/lessons.h"
#include "colour/spectral_render.h"
#include "image/image.h"
#include "scene/scene.h"

namespace glint {

struct ClassroomState {
    // Lessons (app/classroom/lessons_view.h).
    bool lessonListLoaded = false;  // tried to load the list (once, on first use)
    std::string lessonListPath;     // `glint present LIST.json`; empty: the shipped list (lessons.h)
    LessonList lessonList;
    std::string lessonListError;    // why the list could not be loaded, shown in the lesson window
    int lessonIndex = -1;           // the lesson whose scene is open; -1: none
    // The open lesson as read from its file (classroom/lesson_document.h), and the session
    // document it was loaded as; whether the session holds edits beyond the camera, cached per revision.
    std::string lessonScenePath;
    Scene lessonOriginal;
    std::string lessonOriginalJson;
    std::uint64_t lessonDocument = ~0ull;
    mutable std::uint64_t lessonEditsRevision = ~0ull;
    mutable bool lessonEdited = false;
    bool showLessonWindow = false;  // View ▸ Lessons (L)
    bool showLessonNote = true;     // the title-and-note overlay while a lesson is open

    // Colour windows: the CIE matching functions plot (cmf_plot.h) and the spectral render
    // (spectral_view.h) with its settings, its last image (display-encoded) and a message.
    bool showCmfWindow = false;
    bool showSpectralWindow = false;
    SpectralSettings spectral;
    int spectralWidth = 256;           // pixels; the height keeps the scene's aspect
    DisplayImage spectralImage;        // empty until the first render
    std::uint64_t spectralImageRevision = 0;  // a new image to upload
    std::string spectralMessage;       // time taken, or why it could not render
};

}  // namespace glint
