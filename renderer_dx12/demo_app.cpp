// chNN_demo: the DirectX 12 demo shell of chapters 01..NN, compiled once for every chapter
// (demo_app.h; each demo's main, app_main.cpp, only names its chapter).
//   chNN_demo [--scene NAME|FILE.json]                      window with the ImGui shell
//   chNN_demo --scene NAME --frames N --screenshot F.png --hidden   frame N offscreen, exit
//   chNN_demo --frames N                                    window, exit after N presents
//   offscreen scripting for the render tests (scripted.h): --views, --select, --pick X,Y,
//   --select-contact, --rewind K, --open SECTIONS, --draw-every-frame
// Console subsystem on purpose: errors and --list go to stdout/stderr on every platform.
#include "demo_app.h"
#include "expectations.h"
#include "frame.h"
#include "picking.h"
#include "scripted.h"
#include "targets.h"
#include "ui_shell.h"

#include "app/runner.h"
#include "world/scene.h"

#include <CLI/CLI.hpp>
#include <imgui.h>
#include <imgui_impl_dx12.h>
#include <imgui_impl_win32.h>

#include <chrono>
#include <cstdio>
#include <iostream>
#include <memory>

extern IMGUI_IMPL_API LRESULT ImGui_ImplWin32_WndProcHandler(HWND window, UINT message, WPARAM wParam, LPARAM lParam);

namespace stepwise::render {
namespace {

/// The chapter this demo shows (runDemoApp's argument).
int demoChapter = 99;

struct Options {
    std::string scene;
    long frames = -1;
    long lingerFrames = 0;
    std::string screenshot;
    bool hidden = false;
    bool list = false;
    int width = 1280;
    int height = 720;
    // Offscreen scripting (scripted.h).
    std::string views;
    std::string select;
    std::string pick;
    bool selectContact = false;
    int rewind = -1;
    std::string open;
    bool drawEveryFrame = false;
};

std::string title() { return "Stepwise chapter " + std::to_string(demoChapter) + " demo (Direct3D 12)"; }

int pendingWidth = 0, pendingHeight = 0;

LRESULT CALLBACK windowProc(HWND window, UINT message, WPARAM wParam, LPARAM lParam) {
    if (ImGui_ImplWin32_WndProcHandler(window, message, wParam, lParam)) return 1;
    switch (message) {
        case WM_SYSCOMMAND:
            // Alt alone (the debugger's "continue" key) would open the window menu, which then
            // swallows the next key press.
            if ((wParam & 0xfff0) == SC_KEYMENU) return 0;
            return DefWindowProcW(window, message, wParam, lParam);
        case WM_SIZE:
            if (wParam != SIZE_MINIMIZED) {
                pendingWidth = LOWORD(lParam);
                pendingHeight = HIWORD(lParam);
            }
            return 0;
        case WM_DESTROY: PostQuitMessage(0); return 0;
        default: return DefWindowProcW(window, message, wParam, lParam);
    }
}

ShellInfo shellInfo(const Device& device, float fps) { return {title(), device.adapterName(), fps}; }

/// The scripted actions that need the frames stepped but no camera: --rewind, --select.
void scriptBeforeFraming(DemoState& state, const Options& options) {
    if (options.rewind >= 0) {
        const History& history = state.session().history();
        state.rewindTo(std::max(history.oldestFrame(), history.newestFrame() - options.rewind));
        std::cout << "rewound " << options.rewind << " frames: showing frame " << state.world().frame << " (live frame "
                  << state.session().liveFrame() << ")\n";
    }
    if (!options.select.empty()) {
        state.selectedBody = findBody(state.world(), options.select);
        if (state.selectedBody < 0) throw std::invalid_argument("--select: no body '" + options.select + "'");
    }
}

/// The scripted actions that need the framed camera: --pick, --select-contact.
void scriptAfterFraming(DemoState& state, const Options& options, const Camera& camera, float width, float height) {
    if (!options.pick.empty()) {
        float x = 0, y = 0;
        parsePixel(options.pick, x, y);
        const int body = pickBody(state.world(), cursorRay(camera, x + 0.5f, y + 0.5f, width, height));
        state.selectedBody = body;
        if (body >= 0) std::cout << "picked body " << body << " '" << state.world().bodies[static_cast<size_t>(body)].name << "'\n";
        else std::cout << "picked nothing\n";
    }
    if (options.selectContact) {
        const HitTree& tree = state.hitTree();
        if (tree.pointCount() == 0) throw std::runtime_error("--select-contact: no contact points at this frame");
        for (int p = 0; p < static_cast<int>(tree.pairs.size()); ++p)
            if (!tree.pairs[static_cast<size_t>(p)].manifolds.empty() && !tree.pairs[static_cast<size_t>(p)].manifolds[0].points.empty()) {
                state.selectHit(HitSelection{p, 0, 0});
                state.revealSelection = true;
                std::cout << "selected contact: " << describePair(tree.pairs[static_cast<size_t>(p)]) << " / "
                          << describePoint(0, tree.pairs[static_cast<size_t>(p)].manifolds[0].points[0]) << "\n";
                break;
            }
    }
}

/// Offscreen: N fixed steps, then the frame is drawn, read back and written as a PNG.
int runOffscreen(DemoState& state, ViewOptions& view, const Options& options) {
    Device device;
    OffscreenTarget target(device, options.width, options.height);
    SceneRenderer renderer(device);
    initImGui(device);
    ImGuiIO& io = ImGui::GetIO();
    io.DisplaySize = ImVec2(static_cast<float>(options.width), static_cast<float>(options.height));
    io.DeltaTime = 1.0f / 60.0f;
    Camera camera;
    DebugTools tools;
    openSections(options.open, tools);
    DrawList list;
    const auto buildFrame = [&] {
        ImGui_ImplDX12_NewFrame();
        ImGui::NewFrame();
        drawShell(state, view, camera, shellInfo(device, 60), tools);
        updateGizmo(tools.gizmo, state, camera, io.DisplaySize.x, io.DisplaySize.y);
        state.buildDrawList(list, view);
        drawLabels(list, camera, io.DisplaySize.x, io.DisplaySize.y);
        ImGui::Render();
    };
    const auto drawFrame = [&](OffscreenTarget* readback) {
        device.beginFrame();
        recordFrame(device, renderer, target.view(), frameConstants(camera, view, options.width, options.height), list,
                    ImGui::GetDrawData(), readback);
        device.endFrame();
    };
    // Each offscreen frame stands for a displayed one in the performance monitor: a step, or with
    // --draw-every-frame a step and the whole frame drawn (what the window pays, but the present).
    const long frames = std::max(0L, options.frames);
    constexpr long kFramingFrame = 2;
    for (long i = 0; i < frames; ++i) {
        const auto before = std::chrono::steady_clock::now();
        state.step();
        if (options.drawEveryFrame) {
            buildFrame();
            if (i == kFramingFrame) frameScene(camera, state.initialFraming(), view, io.DisplaySize.x, io.DisplaySize.y);
            drawFrame(nullptr);
        }
        tools.perf.sample(std::chrono::duration<double>(std::chrono::steady_clock::now() - before).count());
    }
    scriptBeforeFraming(state, options);
    // Framed as the window frames a new scene (from frame 0), or, once a body is selected, as F
    // frames it then: the A - B overlay of the selected body's pair is beside the bodies now.
    const Framing framed = options.select.empty() ? state.initialFraming() : state.framing();
    // Dear ImGui lays auto-sized windows out over a couple of frames: build six, draw the
    // last. The camera is framed once the panels have their size, so the scene lands between
    // them; a scripted pick follows, and the last frames lay out what it opened (the inspector,
    // the hit tree).
    constexpr int kUiFrames = 6;
    for (int uiFrame = 0; uiFrame < kUiFrames; ++uiFrame) {
        buildFrame();
        if (uiFrame == kFramingFrame) frameScene(camera, framed, view, io.DisplaySize.x, io.DisplaySize.y);
        if (uiFrame == kFramingFrame + 1) scriptAfterFraming(state, options, camera, io.DisplaySize.x, io.DisplaySize.y);
    }
    drawFrame(&target);
    device.waitIdle();
    if (!options.screenshot.empty()) {
        target.savePng(options.screenshot);
        const bool impulses = view.showImpulses && chapterReading("solver") <= state.chapter();
        writeExpectations(options.screenshot + ".txt", state, camera, framed.bounds, impulses, !options.views.empty(),
                          options.width, options.height);
        std::cout << "wrote " << options.screenshot << " (" << options.width << "x" << options.height << ", scene '"
                  << state.world().name << "', frame " << state.world().frame << ")\n";
    }
    shutdownImGui();
    return 0;
}

int runWindow(DemoState& state, ViewOptions& view, const Options& options) {
    const HINSTANCE instance = GetModuleHandleW(nullptr);
    WNDCLASSEXW windowClass = {};
    windowClass.cbSize = sizeof windowClass;
    windowClass.style = CS_CLASSDC;
    windowClass.lpfnWndProc = windowProc;
    windowClass.hInstance = instance;
    windowClass.hCursor = LoadCursor(nullptr, IDC_ARROW);
    windowClass.lpszClassName = L"StepwiseDemo";
    RegisterClassExW(&windowClass);
    RECT rect = {0, 0, options.width, options.height};
    AdjustWindowRect(&rect, WS_OVERLAPPEDWINDOW, FALSE);
    const std::string name = title();
    const HWND window = CreateWindowA("StepwiseDemo", name.c_str(), WS_OVERLAPPEDWINDOW, 40, 40, rect.right - rect.left,
                                      rect.bottom - rect.top, nullptr, nullptr, instance, nullptr);
    if (!window) throw std::runtime_error("CreateWindow failed");

    int exitCode = 0;
    {
        Device device;
        RECT client = {};
        GetClientRect(window, &client);
        SwapChainTarget target(device, window, client.right - client.left, client.bottom - client.top);
        SceneRenderer renderer(device);
        initImGui(device);
        ImGui_ImplWin32_Init(window);
        ShowWindow(window, SW_SHOWDEFAULT);
        UpdateWindow(window);

        Camera camera;
        DebugTools tools;
        DrawList list;
        frameScene(camera, state.initialFraming(), view, float(target.width()), float(target.height()));
        auto last = std::chrono::steady_clock::now();
        const auto start = last;
        float fps = 60;
        long presented = 0;
        long lingering = -1;
        bool running = true;
        while (running) {
            MSG message;
            while (PeekMessageW(&message, nullptr, 0, 0, PM_REMOVE)) {
                TranslateMessage(&message);
                DispatchMessageW(&message);
                if (message.message == WM_QUIT) running = false;
            }
            if (!running) break;
            if (pendingWidth > 0) {
                target.resize(pendingWidth, pendingHeight);
                pendingWidth = pendingHeight = 0;
            }
            const auto now = std::chrono::steady_clock::now();
            const float seconds = std::chrono::duration<float>(now - last).count();
            last = now;
            fps = 0.95f * fps + 0.05f * (seconds > 0 ? 1.0f / seconds : fps);

            ImGui_ImplDX12_NewFrame();
            ImGui_ImplWin32_NewFrame();
            ImGui::NewFrame();
            const float width = float(target.width()), height = float(target.height());
            if (handleInput(state, view, camera, tools, height, seconds)) frameScene(camera, state.framing(), view, width, height);
            tools.perf.sample(seconds);
            state.advance(seconds);
            // The gizmo takes a press on one of its handles; any other click that does not drag
            // (dragging is the camera's) and is not over a window picks in the scene.
            const ImGuiIO& io = ImGui::GetIO();
            const bool gizmoOwnsMouse = updateGizmo(tools.gizmo, state, camera, width, height);
            if (!gizmoOwnsMouse && !io.WantCaptureMouse && ImGui::IsMouseReleased(ImGuiMouseButton_Left) &&
                io.MouseDragMaxDistanceSqr[ImGuiMouseButton_Left] < 16.0f && ImGui::IsMousePosValid())
                clickAt(state, camera, io.MousePos.x, io.MousePos.y, width, height);
            drawShell(state, view, camera, shellInfo(device, fps), tools);
            state.buildDrawList(list, view);
            drawLabels(list, camera, width, height);
            ImGui::Render();

            device.beginFrame();
            const TargetView view3d = target.current();
            recordFrame(device, renderer, view3d, frameConstants(camera, view, view3d.width, view3d.height), list,
                        ImGui::GetDrawData(), nullptr);
            device.endFrame();
            target.present(true);
            if (lingering >= 0 && ++lingering >= options.lingerFrames) running = false;
            if (lingering < 0 && options.frames >= 0 && ++presented >= options.frames) {
                const double total = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
                std::cout << "presented " << presented << " frames of " << view3d.width << "x" << view3d.height << " in "
                          << total << " s (" << 1000.0 * total / double(presented) << " ms per frame)" << std::endl;
                lingering = 0;
                running = options.lingerFrames > 0;
            }
        }
        device.waitIdle();
        ImGui_ImplWin32_Shutdown();
        shutdownImGui();
    }
    DestroyWindow(window);
    return exitCode;
}

int run(int argc, char** argv) {
    CLI::App app{title()};
    Options options;
    app.add_option("--scene", options.scene, "built-in scene name or scene JSON file (default: the chapter's first scene)");
    app.add_option("--frames", options.frames, "offscreen: the frame to draw; window: exit after N frames")
        ->check(CLI::Range(0L, 1000000L));
    app.add_option("--screenshot", options.screenshot, "draw offscreen and write this PNG (plus FILE.png.txt)");
    app.add_option("--linger-frames", options.lingerFrames, "window: frames to keep presenting after --frames")
        ->check(CLI::Range(0L, 100000L));
    app.add_flag("--hidden", options.hidden, "no window: draw offscreen");
    app.add_option("--width", options.width, "image or window width")->check(CLI::Range(16, 8192));
    app.add_option("--height", options.height, "image or window height")->check(CLI::Range(16, 8192));
    app.add_flag("--list", options.list, "list the scenes and exit");
    app.add_option("--views", options.views, std::string("offscreen: exactly these debug views, comma-separated: ") + viewListNames());
    app.add_option("--select", options.select, "offscreen: select this body (name or index)");
    app.add_option("--pick", options.pick, "offscreen: click at pixel X,Y once framed; prints the body picked");
    app.add_flag("--select-contact", options.selectContact, "offscreen: select the first contact point of the hit tree");
    app.add_option("--rewind", options.rewind, "offscreen: after the frames, rewind this many")->check(CLI::Range(0, 100000));
    app.add_flag("--draw-every-frame", options.drawEveryFrame,
                 "offscreen: draw each of the frames, not only the last (the performance monitor then measures whole frames)");
    app.add_option("--open", options.open, "offscreen: open these debugger sections (session, views, hits, inspector, perf)");
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& error) {
        const int code = app.exit(error);
        return code == 0 ? 0 : 2;
    }

    Registry registry;
    registerChapters(registry);
    DemoState state(registry, demoChapter);
    ViewOptions view;
    // Chapter 9 is the debugger's chapter; before it the window starts folded to its title bar.
    view.debuggerOpen = demoChapter >= 9;
    try {
        // Before the scene loads: the A - B overlay is part of what its first framing covers.
        if (!options.views.empty()) applyViewList(options.views, state, view);
    } catch (const std::exception& error) {
        std::cerr << "error: --views: " << error.what() << '\n';
        return 2;
    }
    if (options.list) {
        for (const SceneEntry* scene : state.scenes())
            std::cout << scene->name << "  [chapter " << scene->chapter << ", " << scene->category << "]\n";
        return 0;
    }
    try {
        if (!options.scene.empty()) state.loadByName(options.scene);
        else if (!state.scenes().empty()) {
            // A chapter's demo opens on that chapter's first scene.
            int first = 0;
            for (int i = static_cast<int>(state.scenes().size()) - 1; i >= 0; --i)
                if (state.scenes()[i]->chapter == state.scenes().back()->chapter) first = i;
            state.loadScene(first);
        }
    } catch (const std::exception& error) {
        std::cerr << "error: --scene '" << options.scene << "': " << error.what() << '\n';
        return 2;
    }
    if (!state.loadError.empty()) {
        std::cerr << "error: " << state.loadError << '\n';
        return 2;
    }
    if (options.hidden || !options.screenshot.empty()) return runOffscreen(state, view, options);
    return runWindow(state, view, options);
}

}  // namespace

int runDemoApp(int chapter, int argc, char** argv) {
    demoChapter = chapter;
    try {
        return run(argc, argv);
    } catch (const std::exception& error) {
        std::cerr << "error: " << error.what() << '\n';
        return 1;
    }
}

}  // namespace stepwise::render
