#pragma once
// Named inputs: one table per scene kind (and per material law) that says, for every key a
// user can set, its dotted name ("contact.friction" = key friction of table [contact]), type,
// unit, valid range or choices and a one-line description, and where it lives in the scene's
// struct -- in the spirit of deal.II's declare_parameters and MGIS's named variables. The table
// drives the reading of the scene file (unknown keys are errors; errors name the file, the key
// and the value), the inputs a sweep or a fit may vary (by name, with the same checks), and the
// generated key reference in the documentation (`spifit inputs`).
#include "forward/io/toml_reader.hpp"

#include <functional>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

namespace spifit::io {

// The valid values of a number: an interval with open or closed ends (infinite: unbounded).
struct Range {
  double lo = -std::numeric_limits<double>::infinity(), hi = std::numeric_limits<double>::infinity();
  bool lo_open = false, hi_open = false;
  static Range any() { return {}; }
  static Range positive() { return {0.0, std::numeric_limits<double>::infinity(), true, false}; }
  static Range non_negative() { return {0.0, std::numeric_limits<double>::infinity(), false, false}; }
  static Range closed(double a, double b) { return {a, b, false, false}; }
  static Range at_least(double a) { return {a, std::numeric_limits<double>::infinity(), false, false}; }
  bool contains(double v) const;
  // "> 0", ">= 0", "[2, 2000]", "(0, 1]", "any"
  std::string text() const;
};

// list and table: a TOML array ([a, b]) or inline table ({ k = v }) the scene's reader handles.
enum class InputType { real, integer, boolean, text, list, table };
const char* to_string(InputType t);

// What the reader, a sweep, a fit and the documentation know of an input.
struct InputInfo {
  std::string name;  // dotted: "contact.friction"
  InputType type = InputType::real;
  std::string unit;  // empty for counts, ratios, flags and texts
  Range range;       // numbers
  std::vector<std::string> choices;  // texts (or numbers) with a fixed set of values; empty: any
  std::string doc;   // one line
  bool variable = false;  // a number a sweep may vary or a fit may identify
  std::string table() const { return name.substr(0, name.find('.')); }
  std::string key() const { return name.substr(name.find('.') + 1); }
  // Why v cannot be this input's value ("must be > 0", "takes integer values"), empty if it can.
  std::string check(double v) const;
  std::string check(const std::string& v) const;
};

// A Markdown table of inputs: name, type, unit, valid values, description.
std::string markdown_cell(const std::string& text);  // '|' escaped
std::string markdown_reference(const std::vector<InputInfo>& inputs);

template <typename Owner>
class InputTable {
 public:
  using Real = std::function<double&(Owner&)>;
  using Integer = std::function<int&(Owner&)>;
  using Boolean = std::function<bool&(Owner&)>;
  // A text input read and written through conversions (enums): set returns false for a value
  // it does not know.
  struct Text {
    std::function<std::string(const Owner&)> get;
    std::function<bool(Owner&, const std::string&)> set;
  };

  InputTable& real(InputInfo info, Real field) { return add(std::move(info), InputType::real, Field{std::move(field), {}, {}, {}}); }
  InputTable& integer(InputInfo info, Integer field) { return add(std::move(info), InputType::integer, Field{{}, std::move(field), {}, {}}); }
  InputTable& boolean(InputInfo info, Boolean field) { return add(std::move(info), InputType::boolean, Field{{}, {}, std::move(field), {}}); }
  InputTable& text(InputInfo info, Text field) { return add(std::move(info), InputType::text, Field{{}, {}, {}, std::move(field)}); }
  // An input the scene's reader handles itself (paths relative to the scene file, lists, the
  // tool path): declared for allow_only and the documentation; read() checks a scalar one's
  // type, range and choices (and stores nothing), get/set refuse it.
  InputTable& custom(InputInfo info, InputType type) { return add(std::move(info), type, Field{}); }

  const std::vector<InputInfo>& infos() const { return infos_; }
  const InputInfo* find(const std::string& name) const {
    const std::size_t k = position(name);
    return k < infos_.size() ? &infos_[k] : nullptr;
  }
  // The keys this table declares in TOML table `table` (for allow_only, with the reader's own).
  std::vector<std::string> keys_of(const std::string& table) const {
    std::vector<std::string> keys;
    for (const auto& i : infos_)
      if (i.table() == table) keys.push_back(i.key());
    return keys;
  }
  // Reads every declared key of `table` that t (the TOML table [table]) holds into o, checking
  // types, ranges and choices: io::InputError naming the file, the key and the value. A custom
  // key is checked only (lists and tables not at all): the reader stores it. Keys t holds that
  // are not declared are left to the caller's allow_only.
  void read(const TomlTable& t, const std::string& table, Owner& o) const {
    for (std::size_t k = 0; k < infos_.size(); ++k) {
      const InputInfo& i = infos_[k];
      if (i.table() != table || !t.has(i.key())) continue;
      read_one(t, i, fields_[k], o);
    }
  }
  // Numeric value of a number or flag by name; std::invalid_argument for an unknown or text input.
  double get(const Owner& o, const std::string& name) const {
    const std::size_t k = index(name);
    Owner& w = const_cast<Owner&>(o);  // the field accessors are not const; nothing is written
    const Field& f = fields_[k];
    if (f.real) return f.real(w);
    if (f.integer) return f.integer(w);
    return f.boolean(w) ? 1.0 : 0.0;
  }
  // Sets a number or flag by name: "" when done, else why the value is invalid for it (nothing
  // set). std::invalid_argument for an unknown or text input.
  std::string set(Owner& o, const std::string& name, double v) const {
    const std::size_t k = index(name);
    if (const std::string why = infos_[k].check(v); !why.empty()) return why;
    const Field& f = fields_[k];
    if (f.real) f.real(o) = v;
    else if (f.integer) f.integer(o) = static_cast<int>(v);
    else f.boolean(o) = v != 0.0;
    return {};
  }
  // Whether the input is one the reader handles itself.
  bool is_custom(const std::string& name) const {
    const std::size_t k = position(name);
    return k < infos_.size() && fields_[k].custom();
  }

 private:
  // The accessor of an input: exactly one of them is set, none for a custom input.
  struct Field {
    Real real;
    Integer integer;
    Boolean boolean;
    Text text;
    bool custom() const { return !real && !integer && !boolean && !text.set; }
  };
  std::vector<InputInfo> infos_;
  std::vector<Field> fields_;

  InputTable& add(InputInfo info, InputType type, Field field) {
    if (find(info.name)) throw std::logic_error("input " + info.name + " declared twice");
    info.type = type;
    infos_.push_back(std::move(info));
    fields_.push_back(std::move(field));
    return *this;
  }
  // The input's place in the table; infos_.size() for an unknown name.
  std::size_t position(const std::string& name) const {
    std::size_t k = 0;
    while (k < infos_.size() && infos_[k].name != name) ++k;
    return k;
  }
  // The place of a number or flag that can be set by name.
  std::size_t index(const std::string& name) const {
    const std::size_t k = position(name);
    if (k == infos_.size()) throw std::invalid_argument("unknown input " + name);
    if (infos_[k].type == InputType::text || fields_[k].custom())
      throw std::invalid_argument("input " + name + " is not a number that can be set by name");
    return k;
  }
  static void read_one(const TomlTable& t, const InputInfo& i, const Field& f, Owner& o) {
    const std::string key = i.key();
    if (f.real) {
      const double v = t.number(key);
      if (const std::string why = i.check(v); !why.empty()) t.fail(key, why);
      f.real(o) = v;
    } else if (f.integer) {
      const int v = t.integer(key, 0);
      if (const std::string why = i.check(static_cast<double>(v)); !why.empty()) t.fail(key, why);
      f.integer(o) = v;
    } else if (f.boolean) {
      f.boolean(o) = t.boolean(key, false);
    } else if (f.text.set) {
      const std::string v = t.string(key);
      if (const std::string why = i.check(v); !why.empty()) t.fail(key, why);
      if (!f.text.set(o, v)) t.fail(key, "not a value of " + i.name);
    } else {
      check_custom(t, i);
    }
  }
  // A custom key's value: its type, range and choices (lists and tables are the reader's).
  static void check_custom(const TomlTable& t, const InputInfo& i) {
    const std::string key = i.key();
    std::string why;
    switch (i.type) {
      case InputType::real: why = i.check(t.number(key)); break;
      case InputType::integer: why = i.check(static_cast<double>(t.integer(key, 0))); break;
      case InputType::boolean: (void)t.boolean(key, false); break;
      case InputType::text: why = i.check(t.string(key)); break;
      case InputType::list:
      case InputType::table: break;
    }
    if (!why.empty()) t.fail(key, why);
  }
};

}  // namespace spifit::io
