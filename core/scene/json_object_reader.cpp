// ObjectReader (see json_object_reader.h).
#include "scene/json_object_reader.h"

#include <cmath>
#include <sstream>

#include "util/reference_confinement.h"

namespace glint {
namespace {

std::string typeName(const nlohmann::json& value) {
    if (value.is_number()) return "a number";
    if (value.is_string()) return "a string";
    if (value.is_boolean()) return "a boolean";
    if (value.is_array()) return "an array";
    if (value.is_object()) return "an object";
    return "null";
}

std::string describeBounds(const Bounds& bounds) {
    std::ostringstream text;
    const bool hasMin = bounds.min > -std::numeric_limits<double>::max();
    const bool hasMax = bounds.max < std::numeric_limits<double>::max();
    if (hasMin && hasMax && bounds.minExclusive) text << "greater than " << bounds.min << " and at most " << bounds.max;
    else if (hasMin && hasMax) text << "between " << bounds.min << " and " << bounds.max;
    else if (hasMin) text << (bounds.minExclusive ? "greater than " : "at least ") << bounds.min;
    else if (hasMax) text << "at most " << bounds.max;
    return text.str();
}

}  // namespace

ObjectReader::ObjectReader(const JsonDocument& document, const nlohmann::json& node, std::string pointer,
                           std::string what)
    : document_(document), node_(node), pointer_(std::move(pointer)), what_(std::move(what)) {
    if (!node_.is_object()) failHere(what_ + " must be a JSON object, not " + typeName(node_));
}

void ObjectReader::fail(const std::string& key, const std::string& message) const {
    const std::string memberPointer = appendPointer(pointer_, key);
    throw JsonReadError{makeError(what_ + " '" + key + "': " + message, document_.locate(memberPointer))};
}

void ObjectReader::failHere(const std::string& message) const {
    throw JsonReadError{makeError(message, document_.locate(pointer_))};
}

const nlohmann::json& ObjectReader::take(const std::string& key) {
    known_.insert(key);
    return node_.at(key);
}

double ObjectReader::checkedNumber(const nlohmann::json& value, const std::string& pointer,
                                   const std::string& label, Bounds bounds) const {
    auto refuse = [&](const std::string& message) {
        throw JsonReadError{makeError(what_ + " '" + label + "': " + message, document_.locate(pointer))};
    };
    if (!value.is_number()) refuse("expected a number, found " + typeName(value));
    const double number = value.get<double>();
    if (!std::isfinite(number)) refuse("must be a finite number");
    const bool belowMin = bounds.minExclusive ? number <= bounds.min : number < bounds.min;
    if (belowMin || number > bounds.max) {
        std::ostringstream text;
        text << number << " is out of range: must be " << describeBounds(bounds);
        refuse(text.str());
    }
    return number;
}

double ObjectReader::number(const std::string& key, double fallback, Bounds bounds) {
    known_.insert(key);
    if (!has(key)) return fallback;
    return checkedNumber(node_.at(key), appendPointer(pointer_, key), key, bounds);
}

int ObjectReader::integer(const std::string& key, int fallback, int min, int max) {
    known_.insert(key);
    if (!has(key)) return fallback;
    const nlohmann::json& value = node_.at(key);
    if (!value.is_number_integer()) fail(key, "expected an integer, found " + typeName(value));
    const long long number = value.get<long long>();
    if (number < min || number > max)
        fail(key, std::to_string(number) + " is out of range: must be between " + std::to_string(min) +
                      " and " + std::to_string(max));
    return static_cast<int>(number);
}

bool ObjectReader::boolean(const std::string& key, bool fallback) {
    known_.insert(key);
    if (!has(key)) return fallback;
    const nlohmann::json& value = node_.at(key);
    if (!value.is_boolean()) fail(key, "expected true or false, found " + typeName(value));
    return value.get<bool>();
}

std::string ObjectReader::string(const std::string& key, const std::string& fallback) {
    known_.insert(key);
    if (!has(key)) return fallback;
    const nlohmann::json& value = node_.at(key);
    if (!value.is_string()) fail(key, "expected a string, found " + typeName(value));
    return value.get<std::string>();
}

std::string ObjectReader::requiredString(const std::string& key) {
    if (!has(key)) failHere(what_ + " needs the key '" + key + "'");
    return string(key, "");
}

std::filesystem::path ObjectReader::referencedFile(const std::string& key) {
    const std::string written = requiredString(key);
    auto confined = confinedReference(written, {document_.file(), 0, 0});
    if (!confined) fail(key, confined.error().message);
    return *confined;
}

std::vector<double> ObjectReader::numberArray(const std::string& key, size_t count, Bounds bounds) {
    const nlohmann::json& value = node_.at(key);
    if (!value.is_array() || value.size() != count)
        fail(key, "expected an array of " + std::to_string(count) + " numbers, found " + typeName(value) +
                      (value.is_array() ? " of " + std::to_string(value.size()) : ""));
    std::vector<double> numbers;
    for (size_t i = 0; i < count; ++i)
        numbers.push_back(checkedNumber(value[i], appendPointer(appendPointer(pointer_, key), std::to_string(i)),
                                        key + "[" + std::to_string(i) + "]", bounds));
    return numbers;
}

glm::vec3 ObjectReader::vec3(const std::string& key, glm::vec3 fallback, Bounds bounds) {
    known_.insert(key);
    if (!has(key)) return fallback;
    const auto n = numberArray(key, 3, bounds);
    return {n[0], n[1], n[2]};
}

glm::vec2 ObjectReader::vec2(const std::string& key, glm::vec2 fallback, Bounds bounds) {
    known_.insert(key);
    if (!has(key)) return fallback;
    const auto n = numberArray(key, 2, bounds);
    return {n[0], n[1]};
}

glm::vec4 ObjectReader::vec4(const std::string& key, glm::vec4 fallback, Bounds bounds) {
    known_.insert(key);
    if (!has(key)) return fallback;
    const auto n = numberArray(key, 4, bounds);
    return {n[0], n[1], n[2], n[3]};
}

int ObjectReader::choice(const std::string& key, std::span<const char* const> ids, int fallback) {
    if (!has(key)) {
        known_.insert(key);
        return fallback;
    }
    const std::string value = string(key, "");
    for (size_t i = 0; i < ids.size(); ++i)
        if (value == ids[i]) return static_cast<int>(i);
    std::string list;
    for (const char* id : ids) list += std::string(list.empty() ? "" : ", ") + id;
    fail(key, "unknown value '" + value + "' (expected one of: " + list + ")");
}

ObjectReader ObjectReader::object(const std::string& key) {
    known_.insert(key);
    return ObjectReader(document_, node_.at(key), appendPointer(pointer_, key), key);
}

std::vector<ObjectReader> ObjectReader::objectArray(const std::string& key) {
    known_.insert(key);
    std::vector<ObjectReader> items;
    if (!has(key)) return items;
    const nlohmann::json& value = node_.at(key);
    if (!value.is_array()) fail(key, "expected an array, found " + typeName(value));
    const std::string arrayPointer = appendPointer(pointer_, key);
    for (size_t i = 0; i < value.size(); ++i)
        items.emplace_back(document_, value[i], appendPointer(arrayPointer, std::to_string(i)),
                           key + "[" + std::to_string(i) + "]");
    return items;
}

void ObjectReader::rejectUnknownKeys(std::span<const char* const> extraKnown) {
    known_.insert(extraKnown.begin(), extraKnown.end());
    for (const auto& [key, value] : node_.items()) {
        if (known_.count(key)) continue;
        std::string list;
        for (const std::string& name : known_) list += (list.empty() ? "" : ", ") + name;
        fail(key, "unknown key (known keys here: " + list + ")");
    }
}

ObjectReader readRoot(const JsonDocument& document, const std::string& what) {
    return ObjectReader(document, document.root(), "", what);
}

}  // namespace glint
