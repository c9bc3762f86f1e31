#pragma once
// A small least-recently-used map. `snell eval` sends thousands of probe
// captures that reuse a handful of programs; the cache keeps those compiled
// while bounding what a long run of distinct programs can hold on to.
#include <cstddef>
#include <list>
#include <memory>
#include <string>
#include <unordered_map>
#include <utility>

namespace snell::vk {

template <class Value>
class LruCache {
 public:
  explicit LruCache(std::size_t capacity) : capacity_(capacity ? capacity : 1) {}

  // The entry for `key`, made by `make()` (returning std::unique_ptr<Value>)
  // on a miss. If `make` throws, nothing is cached.
  template <class Make>
  Value& getOrMake(const std::string& key, Make&& make) {
    if (auto found = index_.find(key); found != index_.end()) {
      order_.splice(order_.begin(), order_, found->second);
      return *found->second->second;
    }
    std::unique_ptr<Value> value = make();
    if (order_.size() >= capacity_) {
      index_.erase(order_.back().first);
      order_.pop_back();
    }
    order_.emplace_front(key, std::move(value));
    index_[key] = order_.begin();
    return *order_.front().second;
  }

  // Drops the entry for `key`, if there is one.
  void erase(const std::string& key) {
    if (auto found = index_.find(key); found != index_.end()) {
      order_.erase(found->second);
      index_.erase(found);
    }
  }

 private:
  using Entry = std::pair<std::string, std::unique_ptr<Value>>;
  std::size_t capacity_;
  std::list<Entry> order_;  // most recently used first
  std::unordered_map<std::string, typename std::list<Entry>::iterator> index_;
};

}  // namespace snell::vk
