// Checkpoint files (io/checkpoint_file.hpp) written in pieces and read in part: a distributed
// run's process 0 writes the processes' particles one process at a time, and each process of
// a distributed restart reads only the rows of its region. Both must give exactly the arrays
// a whole write and a whole read give.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <string>

#include "netsph/core/error.hpp"
#include "netsph/io/checkpoint_file.hpp"

namespace netsph {
namespace {

namespace fs = std::filesystem;

fs::path temp_file(const std::string& name) {
  return fs::temp_directory_path() /
         ("netsph_checkpoint_" + std::to_string(::getpid()) + "_" + name + ".h5");
}

/// n rows: "x" (3 doubles each, x[3r] = r / n), "v" (3 floats), "k" (1 byte), "id" (1 u32),
/// and arrays that are not per row: "time" (1 double), "next" (1 u32), a text.
CheckpointData rows_of(std::size_t first, std::size_t n, std::size_t total) {
  CheckpointData c;
  c.f64["x"], c.f32["v"], c.u8["k"], c.u32["id"];  // named even when empty
  for (std::size_t r = first; r < first + n; ++r) {
    const double x = static_cast<double>(r) / static_cast<double>(total);
    c.f64["x"].insert(c.f64["x"].end(), {x, 2 * x, 3 * x});
    c.f32["v"].insert(c.f32["v"].end(), {float(r), float(r) + 0.5f, -float(r)});
    c.u8["k"].push_back(static_cast<std::uint8_t>(r % 4));
    c.u32["id"].push_back(static_cast<std::uint32_t>(1000 + r));
  }
  return c;
}

CheckpointData global_state() {
  CheckpointData c;
  c.f64["time"] = {1.25};
  c.u32["next"] = {4242};
  c.text["case"] = "a case";
  return c;
}

/// The global state and `total` rows in one set of arrays.
CheckpointData whole_state(std::size_t total) {
  CheckpointData all = global_state();
  const CheckpointData rows = rows_of(0, total, total);
  all.f64.insert(rows.f64.begin(), rows.f64.end());
  all.f32.insert(rows.f32.begin(), rows.f32.end());
  all.u8.insert(rows.u8.begin(), rows.u8.end());
  all.u32.insert(rows.u32.begin(), rows.u32.end());
  return all;
}

TEST(CheckpointFile, PiecesMakeTheArraysOfOneWholeWrite) {
  const std::size_t total = 700000;  // more than one chunk of the growing datasets
  const fs::path whole = temp_file("whole"), pieces = temp_file("pieces");
  write_checkpoint_file(whole, whole_state(total));
  // Three pieces, one of them empty (a process that owns no particle).
  write_checkpoint_file(pieces, global_state(), [&](const auto& add) {
    add(rows_of(0, 400000, total));
    add(rows_of(400000, 0, total));
    add(rows_of(400000, total - 400000, total));
  });
  const CheckpointData a = read_checkpoint_file(whole), b = read_checkpoint_file(pieces);
  EXPECT_EQ(a.f64, b.f64);
  EXPECT_EQ(a.f32, b.f32);
  EXPECT_EQ(a.u8, b.u8);
  EXPECT_EQ(a.u32, b.u32);
  EXPECT_EQ(a.text, b.text);
  EXPECT_EQ(b.f64.at("x").size(), 3 * total);
  fs::remove(whole);
  fs::remove(pieces);
}

TEST(CheckpointFile, PiecesMustNameTheSameArrays) {
  const fs::path file = temp_file("mismatch");
  EXPECT_THROW(write_checkpoint_file(file, global_state(),
                                     [&](const auto& add) {
                                       add(rows_of(0, 10, 20));
                                       CheckpointData other = rows_of(10, 10, 20);
                                       other.u8.clear();
                                       add(other);
                                     }),
               Error);
  EXPECT_FALSE(fs::exists(file)) << "a failed write left a checkpoint";
  EXPECT_FALSE(fs::exists(file.string() + ".tmp")) << "a failed write left its temporary file";
}

TEST(CheckpointFile, RowsOfARegionAreThoseOfTheWholeFile) {
  const std::size_t total = 300001;  // a block and then some
  const fs::path file = temp_file("rows");
  write_checkpoint_file(file, whole_state(total));

  CheckpointRows select;
  select.arrays = {"x", "v", "k", "id"};
  select.key_width = 3;
  select.keep = [](std::span<const double> x) { return x[0] >= 0.25 && x[0] < 0.6; };
  const CheckpointData part = read_checkpoint_file(file, select);
  // What the whole read gives, filtered here.
  const CheckpointData whole = read_checkpoint_file(file);
  CheckpointData expected;
  for (std::size_t r = 0; r < total; ++r) {
    if (!select.keep(std::span<const double>(whole.f64.at("x").data() + 3 * r, 3))) continue;
    for (int c = 0; c < 3; ++c) {
      expected.f64["x"].push_back(whole.f64.at("x")[3 * r + c]);
      expected.f32["v"].push_back(whole.f32.at("v")[3 * r + c]);
    }
    expected.u8["k"].push_back(whole.u8.at("k")[r]);
    expected.u32["id"].push_back(whole.u32.at("id")[r]);
  }
  ASSERT_GT(expected.u32["id"].size(), total / 4);
  EXPECT_EQ(part.f64.at("x"), expected.f64["x"]);
  EXPECT_EQ(part.f32.at("v"), expected.f32["v"]);
  EXPECT_EQ(part.u8.at("k"), expected.u8["k"]);
  EXPECT_EQ(part.u32.at("id"), expected.u32["id"]);
  // The arrays that are not rows come whole.
  EXPECT_EQ(part.f64.at("time"), std::vector<double>{1.25});
  EXPECT_EQ(part.u32.at("next"), std::vector<std::uint32_t>{4242});
  EXPECT_EQ(part.text.at("case"), "a case");

  // No rows at all: the rest still comes.
  select.keep = [](std::span<const double>) { return false; };
  const CheckpointData none = read_checkpoint_file(file, select);
  EXPECT_TRUE(none.u32.at("id").empty());
  EXPECT_EQ(none.u32.at("next"), std::vector<std::uint32_t>{4242});
  // Without keep() the key is not even read (a distributed restart reads the case first):
  // rows of 7 values, which 3 x 300001 doubles are not, are then no error.
  CheckpointRows unread = select;
  unread.keep = nullptr;
  unread.key_width = 7;
  const CheckpointData texts = read_checkpoint_file(file, unread);
  EXPECT_TRUE(texts.f64.at("x").empty());
  EXPECT_TRUE(texts.u8.at("k").empty());
  EXPECT_EQ(texts.text.at("case"), "a case");
  unread.keep = select.keep;
  EXPECT_THROW(read_checkpoint_file(file, unread), Error);

  // An array that is not one row per key row is an error naming it.
  select.arrays = {"x", "next"};
  try {
    read_checkpoint_file(file, select);
    ADD_FAILURE() << "expected netsph::Error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("/u32/next"), std::string::npos) << e.what();
  }
  fs::remove(file);
}

}  // namespace
}  // namespace netsph
