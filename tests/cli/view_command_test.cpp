// `zraster view` under a private Xvfb server (tests/cli/with_xvfb.sh): its frames are `zraster
// render`'s bit for bit, scripted input moves the camera and the toggles as the flags would, and
// bad input, a missing display and abrupt exits are refused or survived cleanly.
#include <gtest/gtest.h>
#include <zraster/image_io.hpp>

#include <fstream>
#include <string>

#include <sys/stat.h>

#include "support/test_support.hpp"
#include "view_script.hpp"

namespace zraster::test {
namespace {

// The viewer run under Xvfb; skips the test when Xvfb is not installed.
CommandResult run_viewer(const std::string& arguments, const std::filesystem::path& cwd) {
    const std::string line = "cd '" + cwd.string() +
                             "' && bash '" ZRASTER_SOURCE_DIR
                             "/tests/cli/with_xvfb.sh' '" ZRASTER_CLI "' view " +
                             arguments + " 2>&1 </dev/null";
    return run_shell_line(line);
}

#define VIEWER_OR_SKIP(result)                                         \
    do {                                                               \
        if ((result).exit_code == 77) GTEST_SKIP() << (result).output; \
    } while (0)

void write_view_script(const std::filesystem::path& path, const std::string& text) {
    std::ofstream(path, std::ios::binary) << text;
}

// The same pixels (decoded), and the same size.
::testing::AssertionResult same_image(const std::filesystem::path& a,
                                      const std::filesystem::path& b) {
    const ImageRGBA8 x = read_image_rgba8(a), y = read_image_rgba8(b);
    if (x.width != y.width || x.height != y.height)
        return ::testing::AssertionFailure()
               << x.width << "x" << x.height << " vs " << y.width << "x" << y.height;
    std::size_t differing = 0;
    for (std::size_t i = 0; i < x.rgba.size(); ++i) differing += x.rgba[i] != y.rgba[i];
    if (differing == 0) return ::testing::AssertionSuccess();
    return ::testing::AssertionFailure() << differing << " bytes differ";
}

TEST(ViewCommand, ScreenshotIsTheRenderCommandsImage) {
    const auto dir = temp_dir("view-screenshot");
    for (const std::string scene : {"sphere:200", "builtin:default"}) {
        const CommandResult v =
            run_viewer(scene + " --size 160x120 --no-hud --frames 2 --screenshot view.png", dir);
        VIEWER_OR_SKIP(v);
        ASSERT_EQ(v.exit_code, 0) << v.output;
        EXPECT_NE(v.output.find("view: 2 frames in "), std::string::npos) << v.output;
        const CommandResult r = run_zraster("render " + scene + " --size 160x120 -o r.png", dir);
        ASSERT_EQ(r.exit_code, 0) << r.output;
        EXPECT_TRUE(same_image(dir / "view.png", dir / "r.png")) << scene;
    }
}

// --screenshot goes through OutputFiles as every output does: a 255-byte name is written (the
// temporary's name does not grow with it), a FIFO at the path is refused before the window opens.
TEST(ViewCommand, ScreenshotNamesOfTheLongestLengthAndFifos) {
    const auto dir = temp_dir("view-screenshot-names");
    ASSERT_EQ(::mkfifo((dir / "fifo.png").c_str(), 0600), 0);
    const CommandResult fifo = run_zraster("view sphere:20 --screenshot fifo.png", dir);
    EXPECT_EQ(fifo.exit_code, 2) << fifo.output;
    EXPECT_EQ(fifo.output,
              "zraster: --screenshot fifo.png: cannot write: exists and is not a regular file\n");
    EXPECT_TRUE(std::filesystem::is_fifo(dir / "fifo.png"));
    const std::string name = std::string(251, 'v') + ".png";
    const CommandResult v =
        run_viewer("sphere:20 --size 32x24 --no-hud --frames 1 --screenshot " + name, dir);
    VIEWER_OR_SKIP(v);
    EXPECT_EQ(v.exit_code, 0) << v.output;
    EXPECT_TRUE(std::filesystem::is_regular_file(dir / name));
}

// A frame refused by a budget: with --screenshot the run ends refused (exit 2, its line, no
// screenshot); without one, each refusal is told once on stderr.
TEST(ViewCommand, RefusedFramesAreNotHidden) {
    const auto dir = temp_dir("view-refused");
    const std::string refused =
        "sphere:200 --size 32x24 --no-hud --visibility bsp "
        "--max-bsp-polygons 10 --frames 2";
    const CommandResult shot = run_viewer(refused + " --screenshot s.png", dir);
    VIEWER_OR_SKIP(shot);
    EXPECT_EQ(shot.exit_code, 2) << shot.output;
    EXPECT_EQ(shot.output.rfind("zraster: --screenshot: the last frame was not drawn: sphere:200: "
                                "BSP tree: ",
                                0),
              0u)
        << shot.output;
    EXPECT_EQ(shot.output.find('\n'), shot.output.size() - 1) << shot.output;
    EXPECT_FALSE(std::filesystem::exists(dir / "s.png"));
    const CommandResult told = run_viewer(refused, dir);
    EXPECT_EQ(told.exit_code, 0) << told.output;
    EXPECT_EQ(told.output.rfind("warning: view: frame not drawn: sphere:200: BSP tree: ", 0), 0u)
        << told.output;
    EXPECT_EQ(told.output.find("warning", 1), std::string::npos) << told.output;  // once
}

TEST(ViewCommand, HudDrawsOnlyItsBandAtTheTop) {
    const auto dir = temp_dir("view-hud");
    const CommandResult v =
        run_viewer("sphere:200 --size 320x120 --frames 1 --screenshot hud.png", dir);
    VIEWER_OR_SKIP(v);
    ASSERT_EQ(v.exit_code, 0) << v.output;
    ASSERT_EQ(run_zraster("render sphere:200 --size 320x120 -o r.png", dir).exit_code, 0);
    const ImageRGBA8 hud = read_image_rgba8(dir / "hud.png"),
                     plain = read_image_rgba8(dir / "r.png");
    ASSERT_EQ(hud.rgba.size(), plain.rgba.size());
    int differing_in_band = 0, differing_below = 0;
    for (int y = 0; y < hud.height; ++y)
        for (int x = 0; x < hud.width; ++x) {
            const std::size_t i = (std::size_t(y) * std::size_t(hud.width) + std::size_t(x)) * 4;
            const bool differs =
                hud.rgba[i] != plain.rgba[i] || hud.rgba[i + 1] != plain.rgba[i + 1];
            (y < 12 ? differing_in_band : differing_below) += differs;
        }
    EXPECT_GT(differing_in_band, 500);  // a dark band with white text
    EXPECT_EQ(differing_below, 0);
}

TEST(ViewCommand, ScriptedOrbitAndZoomAreTheOrbitFlag) {
    const auto dir = temp_dir("view-orbit");
    // Dragging 40 pixels left turns the eye 10 degrees towards +x; 8 pixels down raises it 2
    // degrees; one wheel notch in brings it to 0.875 of its distance.
    write_view_script(dir / "orbit.txt",
                      "# orbit and zoom\n0 drag left -40 0\n1 drag left 0 8\n1 wheel 1\n");
    const CommandResult v = run_viewer(
        "sphere:200 --orbit 30,20,3 --size 160x120 --no-hud --frames 3 --script orbit.txt "
        "--screenshot view.png",
        dir);
    VIEWER_OR_SKIP(v);
    ASSERT_EQ(v.exit_code, 0) << v.output;
    EXPECT_NE(v.output.find("view: camera --orbit 40,22,2.625\n"), std::string::npos) << v.output;
    ASSERT_EQ(
        run_zraster("render sphere:200 --orbit 40,22,2.625 --size 160x120 -o r.png", dir).exit_code,
        0);
    EXPECT_TRUE(same_image(dir / "view.png", dir / "r.png"));
    ASSERT_EQ(
        run_zraster("render sphere:200 --orbit 30,20,3 --size 160x120 -o start.png", dir).exit_code,
        0);
    EXPECT_FALSE(same_image(dir / "view.png", dir / "start.png"));
}

TEST(ViewCommand, PanGivesTheEyeAndTargetItPrints) {
    const auto dir = temp_dir("view-pan");
    write_view_script(dir / "pan.txt", "0 drag right 12 -5\n");
    const CommandResult v = run_viewer(
        "builtin:cube --size 160x120 --no-hud --frames 2 --script pan.txt --screenshot view.png",
        dir);
    VIEWER_OR_SKIP(v);
    ASSERT_EQ(v.exit_code, 0) << v.output;
    const std::size_t at = v.output.find("view: camera --eye ");
    ASSERT_NE(at, std::string::npos) << v.output;
    const std::string flags = v.output.substr(at + 13, v.output.find('\n', at) - (at + 13));
    ASSERT_EQ(run_zraster("render builtin:cube --size 160x120 -o r.png " + flags, dir).exit_code,
              0);
    EXPECT_TRUE(same_image(dir / "view.png", dir / "r.png")) << flags;
}

TEST(ViewCommand, KeysSwitchAsTheRenderFlagsDo) {
    const auto dir = temp_dir("view-keys");
    // Flat shading, no culling, D24, then the visibility cycle to BSP (z-buffer -> painter ->
    // bsp); the debug-view key is pressed round its whole cycle, back to none.
    std::string script = "0 key 1\n0 key c\n1 key z\n1 key v\n2 key v\n2 key h\n2 key h\n";
    for (int i = 0; i < 11; ++i) script += "2 key d\n";
    write_view_script(dir / "keys.txt", script);
    const CommandResult v = run_viewer(
        "sphere:200 --size 160x120 --no-hud --frames 3 --script keys.txt --screenshot view.png",
        dir);
    VIEWER_OR_SKIP(v);
    ASSERT_EQ(v.exit_code, 0) << v.output;
    // (D24 changes nothing for BSP: the command refuses --depth-format with it.)
    ASSERT_EQ(run_zraster("render sphere:200 --size 160x120 --shading flat --cull none "
                          "--visibility bsp -o r.png",
                          dir)
                  .exit_code,
              0);
    EXPECT_TRUE(same_image(dir / "view.png", dir / "r.png"));
}

TEST(ViewCommand, ResizingToOnePixelAndQuittingMidFrameAreClean) {
    const auto dir = temp_dir("view-resize");
    // Every toggle once, sizes down to 1x1, a screenshot key, then quit while a frame is drawn.
    write_view_script(dir / "resize.txt",
                      "0 key a\n1 resize 1 1\n2 key w\n2 key o\n3 resize 97 41\n3 key s\n"
                      "4 key v\n4 key v\n4 key v\n4 key v\n5 quit\n");
    const CommandResult v = run_viewer(
        "sphere:200 --size 160x120 --no-hud --script resize.txt --screenshot last.png", dir);
    VIEWER_OR_SKIP(v);
    ASSERT_EQ(v.exit_code, 0) << v.output;
    EXPECT_NE(v.output.find("view: 5 frames in "), std::string::npos) << v.output;
    const ImageRGBA8 last = read_image_rgba8(dir / "last.png");
    EXPECT_EQ(last.width, 97);
    EXPECT_EQ(last.height, 41);
    EXPECT_GE(read_image_rgba8(dir / "zraster-view-1.png").width, 1);  // the s key's
}

// Resizes in a row within one frame: the last one counts (each was carried out: a thousand
// alternating 1x1 and 8192x8192 took minutes before the first frame).
TEST(ViewCommand, ResizesInARowWithinAFrameKeepTheLast) {
    std::string text;
    for (int k = 0; k < 1000; ++k) text += k % 2 ? "0 resize 8192 8192\n" : "0 resize 1 1\n";
    text += "0 key a\n0 resize 5 6\n1 resize 7 8\n1 resize 9 10\n";
    const std::vector<cli::ScriptEvent> events = cli::parse_view_script(text, "s.txt");
    ASSERT_EQ(events.size(), 4u);
    EXPECT_EQ(events[0].event.width, 8192);
    EXPECT_EQ(events[1].event.kind, cli::InputEvent::Kind::Key);
    EXPECT_EQ(events[2].event.width, 5);
    EXPECT_EQ(events[3].frame, 1);
    EXPECT_EQ(events[3].event.width, 9);
    EXPECT_EQ(events[3].event.height, 10);
}

TEST(ViewCommand, BadFilesAreExitTwoWithOneLine) {
    const auto dir = temp_dir("view-bad");
    const CommandResult missing = run_zraster("view /nonexistent/x.obj --frames 1", dir);
    EXPECT_EQ(missing.exit_code, 2) << missing.output;
    EXPECT_TRUE(single_line(missing.output)) << missing.output;
    EXPECT_TRUE(missing.output.starts_with("zraster: /nonexistent/x.obj: ")) << missing.output;

    write_view_script(dir / "bad.txt", "0 key v\n1 jump 3\n");
    const CommandResult script = run_zraster("view sphere:20 --script bad.txt", dir);
    EXPECT_EQ(script.exit_code, 2);
    EXPECT_EQ(script.output,
              "zraster: bad.txt: line 2: unknown event 'jump' (key, drag, wheel, resize, quit)\n");
    write_view_script(dir / "late.txt", "3 key v\n1 key v\n");
    const CommandResult order = run_zraster("view sphere:20 --script late.txt", dir);
    EXPECT_EQ(order.exit_code, 2);
    EXPECT_EQ(order.output,
              "zraster: late.txt: line 2: frame 1 is negative or before the previous event's\n");
    const CommandResult no_script = run_zraster("view sphere:20 --script none.txt", dir);
    EXPECT_EQ(no_script.output, "zraster: none.txt: file not found\n");
    // A FIFO or device is not read (it would block, or never end).
    ASSERT_EQ(::mkfifo((dir / "fifo.txt").c_str(), 0600), 0);
    const CommandResult fifo = run_zraster("view sphere:20 --script fifo.txt", dir);
    EXPECT_EQ(fifo.exit_code, 2);
    EXPECT_EQ(fifo.output, "zraster: fifo.txt: not a regular file\n");
    const CommandResult shot = run_zraster("view sphere:20 --screenshot x.jpg", dir);
    EXPECT_EQ(shot.exit_code, 2);
    EXPECT_EQ(shot.output, "zraster: --screenshot: 'x.jpg' must end in .png\n");
    const CommandResult flags = run_zraster("view sphere:20 --visibility bsp --msaa --aa 4", dir);
    EXPECT_EQ(flags.exit_code, 2);
    EXPECT_TRUE(single_line(flags.output)) << flags.output;
}

// Every number of a script has the range of docs/limits.md, checked before the window opens: the
// message names the script, the line and the range.
TEST(ViewCommand, ScriptNumbersOutOfRangeAreRefusedWithTheirLine) {
    const auto dir = temp_dir("view-script-ranges");
    struct Case {
        const char* script;
        const char* message;
    };
    for (const Case& c :
         {Case{"0 key v\n10000000000 quit\n",
               "zraster: s.txt: line 2: frame 10000000000 is past 10^9 (view --frames' range)\n"},
          Case{"0 drag left 1e9 0\n",
               "zraster: s.txt: line 1: drag by 1e9,0 pixels: DX and DY must be within +-16384\n"},
          Case{"0 drag right 0 -20000\n",
               "zraster: s.txt: line 1: drag by 0,-20000 pixels: DX and DY must be within "
               "+-16384\n"},
          Case{"# zoom\n0 wheel -1e300\n",
               "zraster: s.txt: line 2: wheel by -1e300 notches: must be within +-100\n"},
          // (A resize is a frame of that size: --max-pixels holds, set to 1000 here.)
          Case{"0 resize 200 200\n1 quit\n",
               "zraster: s.txt: a resize to 200x200 at frame 0 is more pixels than --max-pixels "
               "1000\n"}}) {
        SCOPED_TRACE(c.script);
        write_view_script(dir / "s.txt", c.script);
        const CommandResult r =
            run_zraster("view sphere:20 --size 16x16 --max-pixels 1000 --script s.txt", dir);
        EXPECT_EQ(r.exit_code, 2);
        EXPECT_EQ(r.output, c.message);
    }
}

// In-range events without end keep the camera within --orbit's ranges: 300 drags of a whole
// window turn the eye 1.2 million degrees (past --orbit's 1e6) and 20 turns of 100 notches zoom
// by 0.875^2000; the azimuth wraps and the distance stops at 1e-6 radii.
TEST(ViewCommand, EndlessDragsAndZoomStayWithinTheOrbitRanges) {
    const auto dir = temp_dir("view-endless");
    std::string script;
    for (int i = 0; i < 300; ++i) script += "0 drag left 16000 0\n";
    for (int i = 0; i < 20; ++i) script += "0 wheel 100\n";
    write_view_script(dir / "endless.txt", script);
    const CommandResult v = run_viewer(
        "sphere:200 --orbit 30,20,3 --size 32x24 --no-hud --frames 1 --script endless.txt", dir);
    VIEWER_OR_SKIP(v);
    ASSERT_EQ(v.exit_code, 0) << v.output;
    // 30 - 300 x 4000 = -1199970 degrees, which is -90.
    EXPECT_NE(v.output.find("view: camera --orbit -90,20,9.9999999999999995e-07\n"),
              std::string::npos)
        << v.output;
}

TEST(ViewCommand, NoDisplayIsAClearErrorNotACrash) {
    const auto dir = temp_dir("view-no-display");
    const CommandResult r = run_shell_line(
        "cd '" + dir.string() + "' && env -u DISPLAY -u WAYLAND_DISPLAY -u SDL_VIDEODRIVER '" +
        ZRASTER_CLI + "' view sphere:20 --frames 1 2>&1 </dev/null");
    EXPECT_EQ(r.exit_code, 2) << r.output;
    EXPECT_TRUE(single_line(r.output)) << r.output;
    EXPECT_TRUE(r.output.starts_with("zraster: view: cannot open a window (")) << r.output;
    EXPECT_NE(r.output.find("xvfb-run"), std::string::npos) << r.output;
}

// Real X11 keyboard and mouse events (xdotool, tests/cli/view_x11_input.sh) reach the viewer
// through SDL: key 1 gives flat shading, a right drag pans and the wheel zooms; the last frame is
// `zraster render` with the camera the viewer prints and --shading flat.
TEST(ViewCommand, RealX11KeysMouseAndWheelReachTheViewer) {
    const auto dir = temp_dir("view-x11");
    const CommandResult v = run_shell_line(
        "cd '" + dir.string() +
        "' && bash '" ZRASTER_SOURCE_DIR "/tests/cli/with_xvfb.sh' bash '" ZRASTER_SOURCE_DIR
        "/tests/cli/view_x11_input.sh' '" ZRASTER_CLI "' builtin:cube 160x120 2>&1 </dev/null");
    VIEWER_OR_SKIP(v);
    ASSERT_EQ(v.exit_code, 0) << v.output;
    const std::size_t at = v.output.find("view: camera --eye ");
    ASSERT_NE(at, std::string::npos) << v.output;
    const std::string flags = v.output.substr(at + 13, v.output.find('\n', at) - (at + 13));
    ASSERT_EQ(
        run_zraster("render builtin:cube --size 160x120 --shading flat -o moved.png " + flags, dir)
            .exit_code,
        0);
    EXPECT_TRUE(same_image(dir / "view.png", dir / "moved.png")) << flags;
    ASSERT_EQ(run_zraster("render builtin:cube --size 160x120 --shading flat -o still.png", dir)
                  .exit_code,
              0);
    EXPECT_FALSE(same_image(dir / "view.png", dir / "still.png")) << "the camera did not move";
    ASSERT_EQ(
        run_zraster("render builtin:cube --size 160x120 -o phong.png " + flags, dir).exit_code, 0);
    EXPECT_FALSE(same_image(dir / "view.png", dir / "phong.png")) << "key 1 did not arrive";
}

}  // namespace
}  // namespace zraster::test
