#pragma once
// Open-addressing hash map from a small key (packed edge or face) to an int. Edge and face lookup
// during refinement and connectivity building is the hot loop of the mesh package, and
// std::unordered_map's node allocation costs several times more than this linear-probing table.

#include <array>
#include <cstdint>
#include <utility>
#include <vector>

namespace sc::mesh {

/// Key of an undirected edge: the two vertex ids, smaller first, packed in 64 bits.
inline std::uint64_t edgeKey(int a, int b)
{
  if (a > b) std::swap(a, b);
  return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(a)) << 32) |
         static_cast<std::uint32_t>(b);
}

/// Key of a triangular face: the three vertex ids sorted ascending.
using FaceKey = std::array<int, 3>;
inline FaceKey faceKey(int a, int b, int c)
{
  if (a > b) std::swap(a, b);
  if (b > c) std::swap(b, c);
  if (a > b) std::swap(a, b);
  return {a, b, c};
}

struct KeyHash {
  std::size_t operator()(std::uint64_t k) const
  {
    k ^= k >> 33;  // murmur3 finaliser: edge keys are highly structured
    k *= 0xff51afd7ed558ccdULL;
    k ^= k >> 33;
    k *= 0xc4ceb9fe1a85ec53ULL;
    k ^= k >> 33;
    return static_cast<std::size_t>(k);
  }
  std::size_t operator()(const FaceKey& f) const
  {
    std::uint64_t h = static_cast<std::uint32_t>(f[0]);
    h = h * 0x9E3779B97F4A7C15ULL + static_cast<std::uint32_t>(f[1]);
    h = h * 0x9E3779B97F4A7C15ULL + static_cast<std::uint32_t>(f[2]);
    return (*this)(h);
  }
};

// Plain comparisons (std::array's operator== becomes a memcmp call in the probe loop).
inline bool keyEqual(std::uint64_t a, std::uint64_t b) { return a == b; }
inline bool keyEqual(const FaceKey& a, const FaceKey& b)
{
  return a[0] == b[0] && a[1] == b[1] && a[2] == b[2];
}

template <class Key>
struct EmptyKey;
template <>
struct EmptyKey<std::uint64_t> {
  static std::uint64_t value() { return ~std::uint64_t(0); }
};
template <>
struct EmptyKey<FaceKey> {
  static FaceKey value() { return {-1, -1, -1}; }
};

/// Map Key -> int with linear probing. No erase: callers store a sentinel value instead.
template <class Key>
class HashIndexMap {
public:
  explicit HashIndexMap(std::size_t expected = 16) { reserve(expected); }

  void reserve(std::size_t expected)
  {
    std::size_t cap = 16;
    while (cap < 2 * expected)
      cap *= 2;
    if (cap > keys_.size()) rehash(cap);
  }

  std::size_t size() const { return size_; }

  /// Pointer to the value of `key`, or nullptr.
  const int* find(const Key& key) const
  {
    std::size_t i = KeyHash{}(key)&mask_;
    while (true) {
      if (keyEqual(keys_[i], key)) return &values_[i];
      if (keyEqual(keys_[i], empty_)) return nullptr;
      i = (i + 1) & mask_;
    }
  }
  int* find(const Key& key) { return const_cast<int*>(std::as_const(*this).find(key)); }

  /// Insert (key, value) if key is absent. Returns the stored value and whether it was inserted.
  std::pair<int*, bool> insert(const Key& key, int value)
  {
    if (2 * (size_ + 1) > keys_.size()) rehash(2 * keys_.size());
    std::size_t i = KeyHash{}(key)&mask_;
    while (true) {
      if (keyEqual(keys_[i], key)) return {&values_[i], false};
      if (keyEqual(keys_[i], empty_)) {
        keys_[i] = key;
        values_[i] = value;
        ++size_;
        return {&values_[i], true};
      }
      i = (i + 1) & mask_;
    }
  }

  /// Call f(key, value) for every stored entry (in table order, which is deterministic).
  template <class F>
  void forEach(F&& f) const
  {
    for (std::size_t i = 0; i < keys_.size(); ++i)
      if (!keyEqual(keys_[i], empty_)) f(keys_[i], values_[i]);
  }

private:
  void rehash(std::size_t cap)
  {
    std::vector<Key> oldKeys(cap, EmptyKey<Key>::value());
    std::vector<int> oldValues(cap, 0);
    oldKeys.swap(keys_);
    oldValues.swap(values_);
    mask_ = cap - 1;
    size_ = 0;
    for (std::size_t i = 0; i < oldKeys.size(); ++i)
      if (!keyEqual(oldKeys[i], empty_)) insert(oldKeys[i], oldValues[i]);
  }

  Key empty_ = EmptyKey<Key>::value();
  std::vector<Key> keys_;
  std::vector<int> values_;
  std::size_t mask_ = 0;
  std::size_t size_ = 0;
};

}  // namespace sc::mesh
