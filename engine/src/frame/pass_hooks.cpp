#include "bounce/frame/pass_hooks.h"

#include "bounce/core/names.h"

#include <algorithm>

namespace bounce {

void PassHookRegistry::add(PassHookDesc desc, OwnerId owner, std::string origin, std::string technique) {
  hooks_.push_back(Hook{std::move(desc), owner, std::move(origin), std::move(technique), sequence_++});
}

std::vector<const PassHookRegistry::Hook*> PassHookRegistry::at(ExtensionPoint point,
                                                                std::string_view technique) const {
  std::vector<const Hook*> out;
  for (const Hook& h : hooks_)
    if (h.desc.point == point && (h.technique.empty() || equalsIgnoreCase(h.technique, technique)))
      out.push_back(&h);
  std::sort(out.begin(), out.end(), [](const Hook* a, const Hook* b) {
    return a->desc.order != b->desc.order ? a->desc.order < b->desc.order : a->sequence < b->sequence;
  });
  return out;
}

void PassHookRegistry::removeOwnedBy(OwnerId owner) {
  std::erase_if(hooks_, [owner](const Hook& h) { return h.owner == owner; });
}

void DebugViewRegistry::add(DebugViewDesc desc, OwnerId owner, std::string origin) {
  views_.push_back(View{std::move(desc), owner, std::move(origin)});
}

const DebugViewRegistry::View* DebugViewRegistry::find(std::string_view name) const {
  for (const View& v : views_)
    if (equalsIgnoreCase(v.desc.name, name)) return &v;
  return nullptr;
}

void DebugViewRegistry::removeOwnedBy(OwnerId owner) {
  std::erase_if(views_, [owner](const View& v) { return v.owner == owner; });
}

}  // namespace bounce
