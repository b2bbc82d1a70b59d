// ${NAME} expansion for config strings.
#include "core/config/VarExpansion.h"

#include "core/common/Errors.h"

namespace rgnav {
namespace {

bool isNameStart(char c) { return c == '_' || (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z'); }
bool isNameChar(char c) { return isNameStart(c) || (c >= '0' && c <= '9'); }

bool isValidName(std::string_view name) {
  if (name.empty() || !isNameStart(name.front())) return false;
  for (char c : name) {
    if (!isNameChar(c)) return false;
  }
  return true;
}

}  // namespace

std::string expandVariables(std::string_view text, const ConfigVars& vars) {
  std::string out;
  std::size_t pos = 0;
  while (pos < text.size()) {
    const std::size_t open = text.find("${", pos);
    if (open == std::string_view::npos) break;
    out.append(text.substr(pos, open - pos));
    const std::size_t close = text.find('}', open + 2);
    if (close == std::string_view::npos) {
      throw ConfigError("unterminated ${ in \"" + std::string(text) + "\"");
    }
    const std::string name(text.substr(open + 2, close - open - 2));
    if (!isValidName(name)) throw ConfigError("bad variable name ${" + name + "}");
    const auto it = vars.find(name);
    if (it == vars.end()) throw ConfigError("unknown variable ${" + name + "}");
    out += it->second;
    pos = close + 1;
  }
  out.append(text.substr(pos));
  return out;
}

}  // namespace rgnav
