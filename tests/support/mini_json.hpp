#pragma once
// Just enough JSON for the tests to read what a page reports about itself
// (numbers, strings, arrays, objects); throws std::runtime_error otherwise.

#include <cctype>
#include <cstdlib>
#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace mini_json {

struct Value {
    enum class Kind { null, boolean, number, string, array, object } kind = Kind::null;
    double number = 0.0;
    std::string text;
    std::vector<Value> items;
    std::map<std::string, Value> fields;

    [[nodiscard]] const Value& operator[](const std::string& key) const {
        const auto it = fields.find(key);
        if (it == fields.end()) throw std::runtime_error("no field " + key);
        return it->second;
    }
    [[nodiscard]] const Value& operator[](std::size_t k) const { return items.at(k); }
    [[nodiscard]] bool has(const std::string& key) const { return fields.count(key) > 0; }
};

class Parser {
public:
    explicit Parser(const std::string& text) : s_(text) {}
    Value parse() {
        Value v = value();
        skip();
        if (at_ != s_.size()) throw std::runtime_error("trailing text in JSON");
        return v;
    }

private:
    void skip() {
        while (at_ < s_.size() && std::isspace(static_cast<unsigned char>(s_[at_]))) ++at_;
    }
    char peek() {
        skip();
        if (at_ >= s_.size()) throw std::runtime_error("JSON ends early");
        return s_[at_];
    }
    void expect(char c) {
        if (peek() != c) throw std::runtime_error(std::string("JSON: expected ") + c);
        ++at_;
    }
    std::string string() {
        expect('"');
        std::string out;
        while (at_ < s_.size() && s_[at_] != '"') {
            if (s_[at_] == '\\' && at_ + 1 < s_.size()) ++at_;
            out += s_[at_++];
        }
        ++at_;
        return out;
    }
    Value value() {
        Value v;
        const char c = peek();
        if (c == '{') {
            v.kind = Value::Kind::object;
            ++at_;
            if (peek() == '}') return ++at_, v;
            for (;;) {
                const std::string key = string();
                expect(':');
                v.fields[key] = value();
                if (peek() == ',') {
                    ++at_;
                    continue;
                }
                expect('}');
                return v;
            }
        }
        if (c == '[') {
            v.kind = Value::Kind::array;
            ++at_;
            if (peek() == ']') return ++at_, v;
            for (;;) {
                v.items.push_back(value());
                if (peek() == ',') {
                    ++at_;
                    continue;
                }
                expect(']');
                return v;
            }
        }
        if (c == '"') {
            v.kind = Value::Kind::string;
            v.text = string();
            return v;
        }
        if (s_.compare(at_, 4, "true") == 0 || s_.compare(at_, 5, "false") == 0) {
            v.kind = Value::Kind::boolean;
            v.number = s_[at_] == 't' ? 1.0 : 0.0;
            at_ += s_[at_] == 't' ? 4 : 5;
            return v;
        }
        if (s_.compare(at_, 4, "null") == 0) {
            at_ += 4;
            return v;
        }
        char* end = nullptr;
        v.kind = Value::Kind::number;
        v.number = std::strtod(s_.c_str() + at_, &end);
        if (end == s_.c_str() + at_) throw std::runtime_error("JSON: unexpected character");
        at_ = static_cast<std::size_t>(end - s_.c_str());
        return v;
    }

    const std::string& s_;
    std::size_t at_ = 0;
};

inline Value parse(const std::string& text) { return Parser(text).parse(); }

}  // namespace mini_json
