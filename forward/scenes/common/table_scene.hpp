#pragma once
// A Scene (scene.hpp) over a kind's data struct and its input table: name, file, card and the
// named inputs come from them; the kind adds its run, its input files and its cross-checks.
#include "forward/io/named_inputs.hpp"
#include "forward/scenes/common/scene.hpp"

#include <string>

namespace spifit::scene {

template <typename Data>
class TableScene : public Scene {
 public:
  // table may be null: the kind has no numeric inputs of its own (only the card's).
  TableScene(std::string kind, Data data, const io::InputTable<Data>* table) : kind_(std::move(kind)), data_(std::move(data)), table_(table) {}
  const std::string& kind() const override { return kind_; }
  const std::string& name() const override { return data_.name; }
  const std::string& file() const override { return data_.file; }
  const material::MaterialCard* card() const override { return &data_.card; }
  material::MaterialCard* card() override { return &data_.card; }
  const Data& data() const { return data_; }

 protected:
  double own_input(const std::string& name) const override { return table_->get(data_, name); }
  std::string set_own_input(const std::string& name, double value) override { return table_->set(data_, name, value); }
  bool has_own_input(const std::string& name) const override {
    const io::InputInfo* i = table_ ? table_->find(name) : nullptr;
    return i && i->type != io::InputType::text && !table_->is_custom(name);
  }
  std::string kind_;
  Data data_;
  const io::InputTable<Data>* table_;
};

}  // namespace spifit::scene
