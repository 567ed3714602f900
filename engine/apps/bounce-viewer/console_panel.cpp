#include "console_panel.h"

#include <fmt/format.h>
#include <imgui.h>

#include <algorithm>
#include <cstring>

namespace bounce::viewer {

namespace {

ImVec4 colourOf(LineKind kind) {
  switch (kind) {
    case LineKind::Input:
      return {0.6f, 0.8f, 1.0f, 1.0f};
    case LineKind::Warning:
      return {1.0f, 0.8f, 0.3f, 1.0f};
    case LineKind::Error:
      return {1.0f, 0.4f, 0.4f, 1.0f};
    case LineKind::Output:
      break;
  }
  return {0.9f, 0.9f, 0.9f, 1.0f};
}

}  // namespace

ConsolePanel::ConsolePanel(ConsoleLog& log, const Console& console,
                           std::function<void(const std::string&)> run)
    : log_(log), console_(console), run_(std::move(run)) {}

std::string ConsolePanel::complete(const std::string& line, std::vector<std::string>* candidates) const {
  // Only the first word names a variable or command; arguments are left alone.
  const size_t start = line.find_first_not_of(' ');
  if (start == std::string::npos || line.find(' ', start) != std::string::npos) return line;
  const std::string prefix = line.substr(start);
  std::vector<std::string> matches = console_.complete(prefix);
  if (candidates) *candidates = matches;
  if (matches.empty()) return line;
  if (matches.size() == 1) return matches.front() + " ";
  std::string common = matches.front();
  for (const std::string& m : matches) {
    size_t n = 0;
    while (n < common.size() && n < m.size() &&
           std::tolower(uint8_t(common[n])) == std::tolower(uint8_t(m[n])))
      ++n;
    common.resize(n);
  }
  return common.size() > prefix.size() ? common : line;
}

int ConsolePanel::onInputEvent(ImGuiInputTextCallbackData* data) {
  auto* self = static_cast<ConsolePanel*>(data->UserData);
  if (data->EventFlag == ImGuiInputTextFlags_CallbackCompletion) {
    std::vector<std::string> candidates;
    const std::string line(data->Buf, size_t(data->BufTextLen));
    const std::string completed = self->complete(line, &candidates);
    if (candidates.size() > 1) {
      self->log_.add(
          LineKind::Output,
          fmt::format("{} matches: {}", candidates.size(),
                      fmt::join(candidates.begin(),
                                candidates.begin() + std::min<size_t>(candidates.size(), 40), "  ")));
      self->scrollToBottom_ = true;
    }
    if (completed != line) {
      data->DeleteChars(0, data->BufTextLen);
      data->InsertChars(0, completed.c_str());
    }
  } else if (data->EventFlag == ImGuiInputTextFlags_CallbackHistory && !self->history_.empty()) {
    const int n = int(self->history_.size());
    int& pos = self->historyPos_;
    if (data->EventKey == ImGuiKey_UpArrow)
      pos = pos < 0 ? n - 1 : std::max(0, pos - 1);
    else if (data->EventKey == ImGuiKey_DownArrow)
      pos = pos < 0 || pos + 1 >= n ? -1 : pos + 1;
    data->DeleteChars(0, data->BufTextLen);
    data->InsertChars(0, pos < 0 ? "" : self->history_[size_t(pos)].c_str());
  }
  return 0;
}

void ConsolePanel::submit() {
  std::string line(input_.data());
  input_.fill(0);
  refocus_ = true;
  scrollToBottom_ = true;
  if (line.find_first_not_of(' ') == std::string::npos) return;
  historyPos_ = -1;
  // The newest copy of a repeated line moves to the end, as shells do.
  history_.erase(std::remove(history_.begin(), history_.end(), line), history_.end());
  history_.push_back(line);
  run_(line);
}

void ConsolePanel::draw(const DockLayout& layout, bool* open) {
  const ImVec2 display = ImGui::GetIO().DisplaySize;
  placePanel(layout, DockedPanel::Console, 10, display.y * 0.65f, display.x * 0.6f, display.y * 0.33f);
  if (!ImGui::Begin("Console", open)) {
    ImGui::End();
    return;
  }
  const float footer = ImGui::GetStyle().ItemSpacing.y + ImGui::GetFrameHeightWithSpacing();
  ImGui::BeginChild("log", ImVec2(0, -footer), false, ImGuiWindowFlags_HorizontalScrollbar);
  for (const ConsoleLine& line : log_.lines()) {
    ImGui::PushStyleColor(ImGuiCol_Text, colourOf(line.kind));
    ImGui::TextUnformatted(line.kind == LineKind::Input ? ("> " + line.text).c_str() : line.text.c_str());
    ImGui::PopStyleColor();
  }
  if (scrollToBottom_ || ImGui::GetScrollY() >= ImGui::GetScrollMaxY()) ImGui::SetScrollHereY(1.0f);
  scrollToBottom_ = false;
  ImGui::EndChild();
  ImGui::Separator();
  const ImGuiInputTextFlags flags = ImGuiInputTextFlags_EnterReturnsTrue |
                                    ImGuiInputTextFlags_CallbackCompletion |
                                    ImGuiInputTextFlags_CallbackHistory;
  ImGui::PushItemWidth(-1);
  if (ImGui::InputTextWithHint("##input", "r.Name value, help PREFIX, Tab completes", input_.data(),
                               input_.size(), flags, &ConsolePanel::onInputEvent, this))
    submit();
  ImGui::PopItemWidth();
  ImGui::SetItemDefaultFocus();
  if (refocus_) ImGui::SetKeyboardFocusHere(-1);  // keep typing after Enter
  refocus_ = false;
  ImGui::End();
}

}  // namespace bounce::viewer
