#include <sc/io/ParameterListJson.hpp>

#include <Teuchos_Array.hpp>
#include <Teuchos_TwoDArray.hpp>

#include <sstream>

namespace sc::io {

namespace {

using Json = nlohmann::ordered_json;

template <class T>
bool tryArray(const Teuchos::any& value, Json& out)
{
  if (value.type() != typeid(Teuchos::Array<T>)) return false;
  out = Json::array();
  for (const T& v : Teuchos::any_cast<Teuchos::Array<T>>(value))
    out.push_back(v);
  return true;
}

template <class T>
bool tryTwoDArray(const Teuchos::any& value, Json& out)
{
  if (value.type() != typeid(Teuchos::TwoDArray<T>)) return false;
  const auto& a = Teuchos::any_cast<Teuchos::TwoDArray<T>>(value);
  out = Json::array();
  for (typename Teuchos::TwoDArray<T>::size_type i = 0; i < a.getNumRows(); ++i) {
    Json row = Json::array();
    for (const T& v : a[i])
      row.push_back(v);
    out.push_back(row);
  }
  return true;
}

template <class T>
bool tryScalar(const Teuchos::any& value, Json& out)
{
  if (value.type() != typeid(T)) return false;
  out = Teuchos::any_cast<T>(value);
  return true;
}

Json entryToJson(const Teuchos::ParameterEntry& entry)
{
  const Teuchos::any& value = entry.getAny(false);  // false: do not mark as used
  Json out;
  if (tryScalar<bool>(value, out) || tryScalar<int>(value, out) ||
      tryScalar<long long>(value, out) || tryScalar<long>(value, out) ||
      tryScalar<double>(value, out) || tryScalar<float>(value, out) ||
      tryScalar<std::string>(value, out) || tryArray<int>(value, out) ||
      tryArray<long long>(value, out) || tryArray<double>(value, out) ||
      tryArray<std::string>(value, out) || tryTwoDArray<int>(value, out) ||
      tryTwoDArray<long long>(value, out) || tryTwoDArray<double>(value, out) ||
      tryTwoDArray<std::string>(value, out))
    return out;
  std::ostringstream s;
  s << value;  // same text the XML writer would produce
  return s.str();
}

}  // namespace

nlohmann::ordered_json toJson(const Teuchos::ParameterList& list)
{
  Json out = Json::object();
  for (auto it = list.begin(); it != list.end(); ++it) {
    const std::string& name = list.name(it);
    const Teuchos::ParameterEntry& entry = list.entry(it);
    out[name] = entry.isList()
                    ? toJson(Teuchos::any_cast<Teuchos::ParameterList>(entry.getAny(false)))
                    : entryToJson(entry);
  }
  return out;
}

}  // namespace sc::io
