#include "overlay.hpp"

#include "overlay_table.hpp"

#include <imgui.h>

namespace grass_viewer {

const char* const kKeysHelp = "  W A S D, Q E   move (Shift: 4x faster)\n"
                              "  mouse drag     look around (either button)\n"
                              "  wheel          movement speed\n"
                              "  0              the scene's own lod setup\n"
                              "  1 .. 5         quality presets: reference, high, default, low, fastest\n"
                              "  T              debug view: tiers (red geometry, yellow volume, blue image)\n"
                              "  C              debug view: planned cells and macro-cells\n"
                              "  M              MSAA on/off (4 or 1 samples)\n"
                              "  P, F12         screenshot (grass-viewer-N.png in the working directory)\n"
                              "  F1             overlay on/off;  H: these keys\n"
                              "  Esc            quit\n"
                              "  F2             wind on/off (the scene's, or a gusty breeze)\n"
                              "  B              roll a ball from in front of the camera / take it away\n";

void build_overlay(const OverlayInfo& info) {
    ImGui::SetNextWindowPos(ImVec2(8.0f, 8.0f), ImGuiCond_Always);
    ImGui::SetNextWindowBgAlpha(0.55f);
    const ImGuiWindowFlags flags = ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_AlwaysAutoResize |
                                   ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoFocusOnAppearing |
                                   ImGuiWindowFlags_NoNav | ImGuiWindowFlags_NoMove;
    if (!ImGui::Begin("grass", nullptr, flags)) {
        ImGui::End();
        return;
    }
    ImGui::Text("%s  %s", info.backend, info.device.c_str());
    ImGui::Text("%s  quality %s  %ux%u  %s", info.scene.c_str(), info.quality, info.width, info.height,
                info.samples > 1 ? "MSAA 4x" : "no MSAA");
    ImGui::Text("frame %.2f ms (%.1f fps)  plan %.3f ms", info.frame_ms,
                info.frame_ms > 0.0 ? 1000.0 / info.frame_ms : 0.0, info.stats.plan_ms);
    for (const std::string& line : tier_table_lines(info.stats, info.gpu_ms, info.gpu_available)) {
        ImGui::TextUnformatted(line.c_str()); // aligned text in ImGui's monospaced font
    }
    ImGui::Text("blades %llu  triangles %llu", static_cast<unsigned long long>(info.stats.blades_drawn),
                static_cast<unsigned long long>(info.stats.triangles));
    ImGui::Text("camera %.1f, %.1f, %.1f  speed %.1f m/s", info.camera[0], info.camera[1], info.camera[2], info.speed);
    ImGui::Text("wind %s (F2)  ball %s (B)", info.wind ? "on" : "off", info.ball ? "rolling" : "none");
    if (info.debug_tiers || info.debug_cells) {
        ImGui::Text("debug view: %s%s", info.debug_tiers ? "tiers " : "", info.debug_cells ? "cells" : "");
    }
    if (!info.status.empty()) ImGui::TextUnformatted(info.status.c_str());
    if (info.help) {
        ImGui::Separator();
        ImGui::TextUnformatted(kKeysHelp);
    } else {
        ImGui::TextDisabled("H: keys");
    }
    ImGui::End();
}

} // namespace grass_viewer
