// ObjectReader: typed, located access to the members of one JSON object while loading a file.
// Every mistake (wrong type, value out of range, NaN, unknown key) becomes a Diagnostic naming
// file:line:column and the key. Internally it throws JsonReadError; the loaders catch it at
// their boundary and return a Result, so no exception leaves core.
#pragma once

#include <filesystem>
#include <limits>
#include <set>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include <glm/glm.hpp>
#include <nlohmann/json.hpp>

#include "scene/json_document.h"

namespace glint {

struct JsonReadError {
    Diagnostic diagnostic;
};

// Accepted range of a number; NaN and infinities are always refused.
struct Bounds {
    double min = -std::numeric_limits<double>::max();
    double max = std::numeric_limits<double>::max();
    bool minExclusive = false;

    static Bounds any() { return {}; }
    static Bounds nonNegative() { return {0.0}; }
    static Bounds positive() { return {0.0, std::numeric_limits<double>::max(), true}; }
    static Bounds between(double low, double high) { return {low, high}; }
};

class ObjectReader {
public:
    // `what` names the object in messages, e.g. "light" or "camera".
    ObjectReader(const JsonDocument& document, const nlohmann::json& node, std::string pointer,
                 std::string what);

    bool has(const std::string& key) const { return node_.contains(key); }
    const std::string& pointer() const { return pointer_; }
    const std::string& file() const { return document_.file(); }  // the JSON file, for relative paths

    double number(const std::string& key, double fallback, Bounds bounds = Bounds::any());
    int integer(const std::string& key, int fallback, int min, int max);
    bool boolean(const std::string& key, bool fallback);
    std::string string(const std::string& key, const std::string& fallback);
    std::string requiredString(const std::string& key);
    // The file a required string names, resolved against this document's folder and confined to
    // it (util/reference_confinement.h); a refused path fails at the key.
    std::filesystem::path referencedFile(const std::string& key);
    glm::vec3 vec3(const std::string& key, glm::vec3 fallback, Bounds bounds = Bounds::any());
    glm::vec2 vec2(const std::string& key, glm::vec2 fallback, Bounds bounds = Bounds::any());
    glm::vec4 vec4(const std::string& key, glm::vec4 fallback, Bounds bounds = Bounds::any());
    // A string that must be one of `ids`; returns its index.
    int choice(const std::string& key, std::span<const char* const> ids, int fallback);

    ObjectReader object(const std::string& key);
    std::vector<ObjectReader> objectArray(const std::string& key);

    // Marks a key as understood without reading it through this reader.
    const nlohmann::json& take(const std::string& key);

    // Refuses keys nobody read, listing the ones this object understands.
    void rejectUnknownKeys(std::span<const char* const> extraKnown = {});
    // Declares keys this object understands even when absent (for the message above).
    void expect(std::initializer_list<const char*> keys) { known_.insert(keys.begin(), keys.end()); }

    [[noreturn]] void fail(const std::string& key, const std::string& message) const;
    [[noreturn]] void failHere(const std::string& message) const;

    // A number from an arbitrary node (an array element), located at `pointer`.
    double checkedNumber(const nlohmann::json& value, const std::string& pointer,
                         const std::string& label, Bounds bounds) const;

private:
    std::vector<double> numberArray(const std::string& key, size_t count, Bounds bounds);

    const JsonDocument& document_;
    const nlohmann::json& node_;
    std::string pointer_;
    std::string what_;
    std::set<std::string> known_;
};

// The root object of a document, checked to be an object.
ObjectReader readRoot(const JsonDocument& document, const std::string& what);

}  // namespace glint
