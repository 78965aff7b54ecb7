// Occupancy maps and PNG encoding.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "antslam/frontend/image.hpp"
#include "antslam/frontend/map_render.hpp"
#include "antslam/frontend/simulator.hpp"

namespace antslam::frontend {
namespace {

/// One fragment per scan, each scan taken at a known pose in a square room 4 m x 4 m.
struct Room {
  LaserLog log;
  MapLayout layout;
  std::vector<slam::Pose2> frames;
};

Room square_room() {
  World w;
  w.add_polyline({{-2, -2}, {2, -2}, {2, 2}, {-2, 2}}, true);
  SimulationSettings sim;
  sim.range_noise = 0.0;
  sim.field_of_view = 2.0 * 3.141592653589793 * 359.0 / 360.0;
  sim.beams = 720;
  aco::Rng rng(1);
  Room room;
  const std::vector<slam::Pose2> poses{{-0.5, 0.0, 0.0}, {0.5, 0.2, 1.0}};
  for (std::size_t i = 0; i < poses.size(); ++i) {
    room.log.scans.push_back(simulate_scan(w, poses[i], sim, rng));
    // Fragment i holds scan i at its origin; the fragment sits at the scan's true pose.
    room.layout.push_back({MapScan{i, slam::Pose2{}}});
    room.frames.push_back(poses[i]);
  }
  return room;
}

TEST(MapRender, DrawsWallsFreeSpaceAndUnknownWhereTheyAre) {
  const Room room = square_room();
  MapRenderSettings s;
  s.resolution = 0.05;
  s.margin = 0.5;
  s.draw_frames = false;
  const Image image = render_map(room.log, room.layout, room.frames, s);
  // Walls from -2 to 2 m plus 0.5 m margins: 5 m = 100 pixels (+1 for the far wall's cell).
  EXPECT_NEAR(static_cast<double>(image.width()), 100.0, 1.0);
  EXPECT_NEAR(static_cast<double>(image.height()), 100.0, 1.0);
  // Pixel of a world point: x from the left edge, y from the top edge (the map starts 0.5 m
  // beyond the walls, give or take rounding, so walls are looked for one pixel around).
  const auto at = [&](double x, double y, long dx, long dy) {
    return image.at(
        static_cast<std::size_t>(std::floor((x + 2.5) / 0.05) + static_cast<double>(dx)),
        image.height() - 1 -
            static_cast<std::size_t>(std::floor((y + 2.5) / 0.05) + static_cast<double>(dy)));
  };
  EXPECT_EQ(at(0.0, 0.0, 0, 0), (Rgb{255, 255, 255}));    // free, inside
  EXPECT_EQ(at(-2.4, -2.4, 0, 0), (Rgb{205, 205, 205}));  // unknown, outside
  EXPECT_EQ(at(2.4, 0.0, 0, 0), (Rgb{205, 205, 205}));    // unknown, behind a wall
  // Walls: black where fragment 0 saw them most, red (Fig. 4) where fragment 1 did.
  int black = 0, red = 0;
  for (double t = -1.5; t <= 1.5; t += 0.5) {
    for (const auto& [x, y] : {std::pair{2.0, t}, {t, 2.0}, {-2.0, t}, {t, -2.0}}) {
      bool wall = false;
      for (long d = -1; d <= 1; ++d) {
        const Rgb c = x == 2.0 || x == -2.0 ? at(x, y, d, 0) : at(x, y, 0, d);
        black += c == Rgb{0, 0, 0} ? 1 : 0;
        red += c == Rgb{210, 0, 0} ? 1 : 0;
        wall = wall || c == Rgb{0, 0, 0} || c == Rgb{210, 0, 0};
      }
      EXPECT_TRUE(wall) << x << " " << y;
    }
  }
  EXPECT_GT(black, 0);
  EXPECT_GT(red, 0);
  s.tint_alternate = false;
  const Image plain = render_map(room.log, room.layout, room.frames, s);
  for (std::size_t y = 0; y < plain.height(); ++y)
    for (std::size_t x = 0; x < plain.width(); ++x) EXPECT_NE(plain.at(x, y), (Rgb{210, 0, 0}));
}

TEST(MapRender, FollowsTheFragmentPosesItIsGiven) {
  const Room room = square_room();
  MapRenderSettings s;
  s.draw_frames = false;
  s.tint_alternate = false;
  // Moving every fragment by 1 m moves the map by 1 m: same image, same size.
  std::vector<slam::Pose2> moved;
  for (const slam::Pose2& f : room.frames) moved.push_back(slam::Pose2{1.0, -3.0, 0.0} * f);
  const Image a = render_map(room.log, room.layout, room.frames, s);
  const Image b = render_map(room.log, room.layout, moved, s);
  ASSERT_EQ(a.width(), b.width());
  std::size_t differ = 0;
  for (std::size_t y = 0; y < a.height(); ++y)
    for (std::size_t x = 0; x < a.width(); ++x) differ += a.at(x, y) == b.at(x, y) ? 0U : 1U;
  EXPECT_LT(differ, a.width() * a.height() / 100);  // cell boundaries may shift by rounding
  // A wrong fragment pose doubles the walls: more occupied pixels.
  std::vector<slam::Pose2> wrong = room.frames;
  wrong[1] = slam::Pose2{0.3, 0.0, 0.0} * wrong[1];
  const Image c = render_map(room.log, room.layout, wrong, s);
  std::size_t doubled = 0;  // walls where the true map has none
  for (std::size_t y = 0; y < c.height(); ++y)
    for (std::size_t x = 0; x < c.width(); ++x)
      doubled += c.at(x, y) == Rgb{0, 0, 0} && a.at(x, y) != Rgb{0, 0, 0} ? 1U : 0U;
  EXPECT_GT(doubled, 60U);  // the shifted copies of the two walls across the shift
  EXPECT_GT(doubled, 5 * differ);
  EXPECT_THROW(render_map(room.log, room.layout, std::vector<slam::Pose2>(1), s),
               std::invalid_argument);
}

TEST(MapRender, AverageOfIdenticalTrialsIsTheirMap) {
  const Room room = square_room();
  MapRenderSettings s;
  const std::vector<std::vector<slam::Pose2>> same{room.frames, room.frames};
  const Image avg = render_average_map(room.log, room.layout, same, s);
  const Image one = render_average_map(room.log, room.layout,
                                       std::vector<std::vector<slam::Pose2>>{room.frames}, s);
  ASSERT_EQ(avg.width(), one.width());
  for (std::size_t y = 0; y < avg.height(); y += 7)
    for (std::size_t x = 0; x < avg.width(); x += 7) EXPECT_EQ(avg.at(x, y), one.at(x, y));
  // Unknown cells are mid-grey, the room's inside white-ish, walls dark.
  EXPECT_EQ(one.at(0, 0), (Rgb{128, 128, 128}));
  EXPECT_GT(one.at(one.width() / 2, one.height() / 2).r, 200);
}

TEST(MapRender, ALargeMapIsDrawnAtTheFinestResolutionThatFits) {
  const Room room = square_room();
  MapRenderSettings s;
  s.resolution = 0.01;
  s.margin = 0.0;
  const std::vector<std::vector<slam::Pose2>> trials{room.frames};
  // The walls span 4 m x 4 m (hits up to the walls' outer cells): 400 x 400 cells fit 1e6.
  EXPECT_DOUBLE_EQ(fitting_resolution(room.log, room.layout, trials, s), 0.01);
  s.max_pixels = 40000;  // 200 x 200 cells: about 2 cm
  const double coarse = fitting_resolution(room.log, room.layout, trials, s);
  EXPECT_GE(coarse, 0.02);
  EXPECT_LE(coarse, 0.021);
  EXPECT_NEAR(coarse * 1000.0, std::round(coarse * 1000.0), 1e-9);  // whole millimetres
  EXPECT_THROW(render_map(room.log, room.layout, room.frames, s), std::invalid_argument);
  s.resolution = coarse;
  const Image image = render_map(room.log, room.layout, room.frames, s);
  EXPECT_LE(image.width() * image.height(), s.max_pixels);
  // One millimetre finer would not fit.
  s.resolution = coarse - 0.001;
  EXPECT_THROW(render_map(room.log, room.layout, room.frames, s), std::invalid_argument);
}

TEST(Png, RoundTripsAndRejectsGarbage) {
  Image image(7, 3, Rgb{1, 2, 3});
  image.at(6, 2) = Rgb{250, 0, 9};
  const std::string bytes = encode_png(image);
  EXPECT_EQ(bytes.substr(1, 3), "PNG");
  const Image back = decode_png(bytes);
  ASSERT_EQ(back.width(), 7U);
  ASSERT_EQ(back.height(), 3U);
  EXPECT_EQ(back.at(6, 2), (Rgb{250, 0, 9}));
  EXPECT_EQ(back.at(0, 0), (Rgb{1, 2, 3}));
  EXPECT_THROW(decode_png("not a png"), std::runtime_error);
  EXPECT_THROW(decode_png(bytes.substr(0, bytes.size() / 2)), std::runtime_error);
}

}  // namespace
}  // namespace antslam::frontend
