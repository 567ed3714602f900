// The scene outliner: materials and lights with the parameters plugins declared for
// them (flags as checkboxes). Edits go through Scene::editMaterial / editLight, which
// record the change, so techniques that cache per-object work (a voxelizer) redo it.

#include "panels.h"
#include "viewer.h"

#include <fmt/format.h>
#include <imgui.h>

namespace bounce::viewer {

namespace {

const char* lightTypeName(LightType t) {
  switch (t) {
    case LightType::Directional:
      return "directional";
    case LightType::Point:
      return "point";
    case LightType::Spot:
      return "spot";
  }
  return "light";
}

/// One plugin-declared parameter of one object; returns the new value when edited.
std::optional<ObjectParameterValue> parameterWidget(const ObjectParameterRegistry::Entry& p,
                                                    const ObjectParameterValues& values) {
  const ObjectParameterValue* set = values.find(p.name);
  const CVar& def = *p.defaultValue;
  const std::string label = fmt::format("{}{}##{}", p.displayName.empty() ? p.name : p.displayName,
                                        set ? "" : " (default)", p.name);
  std::optional<ObjectParameterValue> edited;
  switch (def.type()) {
    case CVarType::Bool: {
      bool v = set ? detail::convertParameter<bool>(*set) : def.getBool();
      if (ImGui::Checkbox(label.c_str(), &v)) edited = v;
      break;
    }
    case CVarType::Float: {
      float v = set ? detail::convertParameter<float>(*set) : def.getFloat();
      if (ImGui::DragFloat(label.c_str(), &v, 0.01f, def.min() ? float(*def.min()) : 0.0f,
                           def.max() ? float(*def.max()) : 0.0f))
        edited = v;
      break;
    }
    default: {
      int v = set ? detail::convertParameter<int32_t>(*set) : def.getInt();
      if (ImGui::DragInt(label.c_str(), &v, 0.2f, def.min() ? int(*def.min()) : 0,
                         def.max() ? int(*def.max()) : 0))
        edited = int32_t(v);
      break;
    }
  }
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("%s\nextras key \"%s\" (%s)%s", p.help.c_str(), p.name.c_str(), p.category.c_str(),
                      set ? "" : "\nnot set by the scene: the default applies");
  return edited;
}

}  // namespace

void drawScenePanel(Viewer& viewer, bool* open) {
  const ImVec2 display = ImGui::GetIO().DisplaySize;
  placePanel(viewer.dockLayout(), DockedPanel::Scene, display.x - 430, display.y * 0.5f + 40, 420,
             display.y * 0.45f - 50);
  if (!ImGui::Begin("Scene", open)) {
    ImGui::End();
    return;
  }
  Scene& scene = *viewer.engine().scene();
  const ObjectParameterRegistry& parameters = viewer.engine().parameters();
  ImGui::TextDisabled("%s", scene.sourcePath().c_str());
  ImGui::TextDisabled("%zu instances, %zu triangles, %zu cameras, revision %llu", scene.instances().size(),
                      scene.triangleCount(), scene.cameras().size(), (unsigned long long)scene.revision());

  if (ImGui::CollapsingHeader(fmt::format("Materials ({})", scene.materials().size()).c_str(),
                              ImGuiTreeNodeFlags_DefaultOpen)) {
    const auto declared = parameters.list(ObjectKind::Material);
    for (uint32_t i = 0; i < scene.materials().size(); ++i) {
      const Material& m = scene.materials()[i];
      ImGui::PushID(int(i));
      if (ImGui::TreeNode("material", "%s",
                          m.name.empty() ? fmt::format("material {}", i).c_str() : m.name.c_str())) {
        glm::vec3 base(m.baseColorFactor);
        if (ImGui::ColorEdit3("base colour", &base.x))
          scene.editMaterial(i,
                             [&](Material& x) { x.baseColorFactor = glm::vec4(base, x.baseColorFactor.a); });
        float strength = m.emissiveStrength;
        if (ImGui::DragFloat("emissive strength", &strength, 0.1f, 0.0f, 1e6f))
          scene.editMaterial(i, [&](Material& x) { x.emissiveStrength = strength; });
        for (const ObjectParameterRegistry::Entry* p : declared)
          if (auto v = parameterWidget(*p, m.parameters))
            scene.editMaterial(i, [&](Material& x) { x.parameters.set(p->name, *v); });
        if (declared.empty()) ImGui::TextDisabled("no plugin declares material parameters");
        ImGui::TreePop();
      }
      ImGui::PopID();
    }
  }
  if (ImGui::CollapsingHeader(fmt::format("Lights ({})", scene.lights().size()).c_str(),
                              ImGuiTreeNodeFlags_DefaultOpen)) {
    const auto declared = parameters.list(ObjectKind::Light);
    for (uint32_t i = 0; i < scene.lights().size(); ++i) {
      const Light& l = scene.lights()[i];
      ImGui::PushID(int(1000000 + i));
      if (ImGui::TreeNode("light", "%s (%s)",
                          l.name.empty() ? fmt::format("light {}", i).c_str() : l.name.c_str(),
                          lightTypeName(l.type))) {
        glm::vec3 colour = l.color;
        if (ImGui::ColorEdit3("colour", &colour.x)) scene.editLight(i, [&](Light& x) { x.color = colour; });
        float intensity = l.intensity;
        if (ImGui::DragFloat(l.type == LightType::Directional ? "irradiance W/m2" : "intensity W/sr",
                             &intensity, 0.1f, 0.0f, 1e6f))
          scene.editLight(i, [&](Light& x) { x.intensity = intensity; });
        bool shadows = l.castShadows;
        if (ImGui::Checkbox("casts shadows", &shadows))
          scene.editLight(i, [&](Light& x) { x.castShadows = shadows; });
        for (const ObjectParameterRegistry::Entry* p : declared)
          if (auto v = parameterWidget(*p, l.parameters))
            scene.editLight(i, [&](Light& x) { x.parameters.set(p->name, *v); });
        if (declared.empty()) ImGui::TextDisabled("no plugin declares light parameters");
        ImGui::TreePop();
      }
      ImGui::PopID();
    }
  }
  ImGui::End();
}

}  // namespace bounce::viewer
