// Plays a bag of the office run into stereonav_node, against a rosmaster this test starts on the
// loopback interface, and compares the grid the node publishes with the one `stereonav map`
// makes offline from the same frames.
#include <arpa/inet.h>
#include <gtest/gtest.h>
#include <mrpt/ros1bridge/map.h>
#include <nav_msgs/OccupancyGrid.h>
#include <nav_msgs/Odometry.h>
#include <netinet/in.h>
#include <ros/ros.h>
#include <rosbag/bag.h>
#include <rosbag/view.h>
#include <sensor_msgs/CameraInfo.h>
#include <sensor_msgs/Image.h>
#include <signal.h>
#include <spawn.h>
#include <std_msgs/UInt32.h>
#include <tf2_msgs/TFMessage.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <iostream>
#include <map>
#include <memory>
#include <mutex>
#include <thread>

#include "mapping/map_outputs.h"
#include "mapping/rawlog_mapping.h"
#include "occupancy_grid/grid_conversion.h"
#include "ros_bridge/rosbag_conversion.h"

extern char** environ;

namespace stereonav {
namespace {

const std::string kSource = STEREONAV_SOURCE_DIR;
const std::string kBinaries = std::string(STEREONAV_BINARY_DIR) + "/bin";

int freeLoopbackPort() {
  const int socket_fd = ::socket(AF_INET, SOCK_STREAM, 0);
  sockaddr_in address{};
  address.sin_family = AF_INET;
  address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  socklen_t length = sizeof address;
  ::bind(socket_fd, reinterpret_cast<sockaddr*>(&address), sizeof address);
  ::getsockname(socket_fd, reinterpret_cast<sockaddr*>(&address), &length);
  ::close(socket_fd);
  return ntohs(address.sin_port);
}

// A child process, stopped with SIGINT (as Ctrl-C) when the test ends.
class ChildProcess {
 public:
  explicit ChildProcess(std::vector<std::string> arguments) {
    std::vector<char*> argv;
    for (std::string& argument : arguments) argv.push_back(argument.data());
    argv.push_back(nullptr);
    if (::posix_spawnp(&pid_, argv[0], nullptr, nullptr, argv.data(), environ) != 0) pid_ = -1;
  }
  ~ChildProcess() { stop(); }
  bool started() const { return pid_ > 0; }
  // Waits for the process to end by itself; its exit status (-1 if it did not exit normally).
  int wait() {
    if (pid_ <= 0) return exit_status_;
    int status = 0;
    ::waitpid(pid_, &status, 0);
    pid_ = -1;
    return exit_status_ = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  }
  // SIGINT, then the exit status (or -1 if it had to be killed).
  int stop() {
    if (pid_ <= 0) return exit_status_;
    ::kill(pid_, SIGINT);
    int status = 0;
    for (int i = 0; i < 300; ++i) {
      if (::waitpid(pid_, &status, WNOHANG) == pid_) {
        pid_ = -1;
        return exit_status_ = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(100));
    }
    ::kill(pid_, SIGKILL);
    ::waitpid(pid_, &status, 0);
    pid_ = -1;
    return exit_status_ = -1;
  }

 private:
  pid_t pid_ = -1;
  int exit_status_ = -1;
};

template <typename Condition>
bool waitFor(Condition condition, double seconds) {
  const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
  while (std::chrono::steady_clock::now() < end) {
    if (condition()) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  return condition();
}

std::string readFile(const std::string& path) {
  std::ifstream file(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(file), std::istreambuf_iterator<char>()};
}

int runChild(std::vector<std::string> arguments) {
  ChildProcess child(std::move(arguments));
  return child.wait();
}

// A rosmaster of our own on a free loopback port, and this process as a ROS node talking to it.
class StereonavNodeTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    directory_ = std::filesystem::temp_directory_path() / ("stereonav_node_test_" + std::to_string(::getpid()));
    std::filesystem::create_directories(directory_);
    const int port = freeLoopbackPort();
    ::setenv("ROS_MASTER_URI", ("http://127.0.0.1:" + std::to_string(port)).c_str(), 1);
    ::setenv("ROS_IP", "127.0.0.1", 1);
    ::setenv("ROS_HOME", directory_.c_str(), 1);
    ::setenv("ROS_LOG_DIR", directory_.c_str(), 1);
    master_ = std::make_unique<ChildProcess>(std::vector<std::string>{"rosmaster", "--core", "-p", std::to_string(port)});
    int argc = 1;
    char name[] = "stereonav_node_test";
    char* argv[] = {name, nullptr};
    ros::init(argc, argv, "stereonav_node_test", ros::init_options::NoSigintHandler);
    master_up_ = master_->started() && waitFor([] { return ros::master::check(); }, 30.0);
  }
  static void TearDownTestSuite() {
    ros::shutdown();
    master_.reset();
    std::filesystem::remove_all(directory_);
  }
  void SetUp() override {
    ASSERT_TRUE(master_up_) << "rosmaster did not start (scripts/setup installs python3-rosmaster)";
  }
  static std::string path(const std::string& name) { return (directory_ / name).string(); }

  // What the node published after the whole bag, played `speed_up` times faster than recorded.
  struct Playback {
    nav_msgs::OccupancyGrid map;
    uint32_t frames_mapped = 0;
    double seconds_after_last_message = 0.0;  // until the last frame was mapped and published
    int node_exit_status = -1;
  };
  // How the bag's odometry reaches the node.
  enum class Odometry { kTopic, kTf };
  Playback play(const std::string& bag_path, const std::string& config, double speed_up,
                uint32_t frames, const std::string& node_output_prefix, bool one_core,
                Odometry odometry = Odometry::kTopic);

  static std::filesystem::path directory_;
  static std::unique_ptr<ChildProcess> master_;
  static bool master_up_;
};

std::filesystem::path StereonavNodeTest::directory_;
std::unique_ptr<ChildProcess> StereonavNodeTest::master_;
bool StereonavNodeTest::master_up_ = false;

StereonavNodeTest::Playback StereonavNodeTest::play(const std::string& bag_path, const std::string& config,
                                                    double speed_up, uint32_t frames,
                                                    const std::string& node_output_prefix, bool one_core,
                                                    Odometry odometry) {
  std::vector<std::string> command{kBinaries + "/stereonav_node", "_config:=" + config,
                                   "_map_every_frames:=1", "_output_prefix:=" + node_output_prefix};
  // Every parameter is given: the master keeps a private parameter after its node has ended.
  command.push_back(std::string("_odometry_source:=") + (odometry == Odometry::kTf ? "tf" : "topic"));
  if (one_core) command.insert(command.begin(), {"taskset", "-c", "0"});
  ChildProcess node(command);
  EXPECT_TRUE(node.started());

  ros::NodeHandle handle;
  std::mutex mutex;
  Playback playback;
  auto map_subscriber = handle.subscribe<nav_msgs::OccupancyGrid>(
      "map", 5, [&](const nav_msgs::OccupancyGrid::ConstPtr& map) {
        std::lock_guard<std::mutex> lock(mutex);
        playback.map = *map;
      });
  auto frames_subscriber = handle.subscribe<std_msgs::UInt32>(
      "frames_mapped", 5, [&](const std_msgs::UInt32::ConstPtr& mapped) {
        std::lock_guard<std::mutex> lock(mutex);
        playback.frames_mapped = mapped->data;
      });
  ros::AsyncSpinner spinner(1);
  spinner.start();

  // One publisher per topic of the bag; playing starts when the node listens to all of them.
  rosbag::Bag bag(bag_path, rosbag::bagmode::Read);
  std::map<std::string, ros::Publisher> publishers;
  for (const rosbag::ConnectionInfo* connection : rosbag::View(bag).getConnections()) {
    const std::string& topic = connection->topic;
    if (connection->datatype == "sensor_msgs/Image") {
      publishers[topic] = handle.advertise<sensor_msgs::Image>(topic, 100);
    } else if (connection->datatype == "sensor_msgs/CameraInfo") {
      publishers[topic] = handle.advertise<sensor_msgs::CameraInfo>(topic, 100);
    } else if (odometry == Odometry::kTopic) {
      publishers[topic] = handle.advertise<nav_msgs::Odometry>(topic, 100);
    }
  }
  EXPECT_EQ(publishers.size(), odometry == Odometry::kTopic ? 7u : 6u);  // 3 x (image, info) + odom
  // tf is published here rather than by a tf2_ros::TransformBroadcaster so that playing waits for
  // the node's listener too: a transform sent before it connects is lost, and its capture is then
  // mapped at the last pose.
  if (odometry == Odometry::kTf) publishers["/tf"] = handle.advertise<tf2_msgs::TFMessage>("/tf", 100);
  for (auto& [topic, publisher] : publishers) {
    EXPECT_TRUE(waitFor([&] { return publisher.getNumSubscribers() > 0; }, 30.0))
        << "stereonav_node did not subscribe to " << topic;
  }

  rosbag::View view(bag);
  const ros::Time begin = view.getBeginTime();
  const ros::Time last_stamp = view.getEndTime();
  const auto start = std::chrono::steady_clock::now();
  for (const rosbag::MessageInstance& message : view) {
    std::this_thread::sleep_until(start + std::chrono::duration<double>((message.getTime() - begin).toSec() / speed_up));
    ros::Publisher& publisher = publishers[message.getTopic()];
    if (const auto image = message.instantiate<sensor_msgs::Image>()) publisher.publish(image);
    if (const auto info = message.instantiate<sensor_msgs::CameraInfo>()) publisher.publish(info);
    const auto odometry_message = message.instantiate<nav_msgs::Odometry>();
    if (odometry_message && odometry == Odometry::kTopic) publisher.publish(odometry_message);
    if (odometry_message && odometry == Odometry::kTf) {
      geometry_msgs::TransformStamped transform;
      transform.header = odometry_message->header;
      transform.child_frame_id = odometry_message->child_frame_id;
      transform.transform.translation.x = odometry_message->pose.pose.position.x;
      transform.transform.translation.y = odometry_message->pose.pose.position.y;
      transform.transform.translation.z = odometry_message->pose.pose.position.z;
      transform.transform.rotation = odometry_message->pose.pose.orientation;
      tf2_msgs::TFMessage transforms;
      transforms.transforms.push_back(transform);
      publishers["/tf"].publish(transforms);
    }
  }
  const auto played = std::chrono::steady_clock::now();
  const bool complete = waitFor([&] {
    std::lock_guard<std::mutex> lock(mutex);
    return playback.frames_mapped == frames && playback.map.header.stamp == last_stamp;
  }, 60.0);
  playback.seconds_after_last_message = std::chrono::duration<double>(std::chrono::steady_clock::now() - played).count();
  EXPECT_TRUE(complete) << "the node mapped " << playback.frames_mapped << " of " << frames << " frames";
  spinner.stop();
  playback.node_exit_status = node.stop();
  std::lock_guard<std::mutex> lock(mutex);
  return playback;
}

// The offline map of `rawlog` (`stereonav map`, odometry poses) as the node publishes maps.
nav_msgs::OccupancyGrid offlineMap(const std::string& rawlog, const MappingOptions& options,
                                   const std::string& output_prefix) {
  nav_msgs::OccupancyGrid offline;
  MappingJob job;
  job.rawlog_path = rawlog;
  job.output_prefix = output_prefix;
  MappingCallbacks callbacks;
  callbacks.on_frame = [&](size_t, const mrpt::maps::CMetricMap& map) {
    mrpt::ros1bridge::toROS(toMrptOccupancyGrid(gridOfMap(map, options.grid.stereo.update.scale)), offline);
  };
  mapRawlog(options, job, callbacks);
  return offline;
}

void expectSameGrid(const nav_msgs::OccupancyGrid& node, const nav_msgs::OccupancyGrid& offline) {
  EXPECT_EQ(node.header.frame_id, "odom");
  EXPECT_EQ(node.info.width, offline.info.width);
  EXPECT_EQ(node.info.height, offline.info.height);
  EXPECT_FLOAT_EQ(node.info.resolution, offline.info.resolution);
  EXPECT_DOUBLE_EQ(node.info.origin.position.x, offline.info.origin.position.x);
  EXPECT_DOUBLE_EQ(node.info.origin.position.y, offline.info.origin.position.y);
  ASSERT_EQ(node.data.size(), offline.data.size());
  size_t differing = 0, known = 0;
  for (size_t i = 0; i < offline.data.size(); ++i) {
    differing += node.data[i] != offline.data[i];
    known += offline.data[i] >= 0;
  }
  EXPECT_EQ(differing, 0u) << "of " << offline.data.size() << " cells";
  EXPECT_GT(known, 1000u);  // the map holds the run, not an empty grid
}

// The office run (76 trinocular frames, 160x120) as a bag `<name>.bag`, and its offline map
// (`<name>_offline.*`).
const std::string kOfficeConfig = kSource + "/ini/office_run.ini";

nav_msgs::OccupancyGrid officeBagAndOfflineMap(const std::string& prefix) {
  const std::string rawlog = kSource + "/rawlogs/office_run.rawlog";
  const MappingOptions options = loadMappingOptionsFile(kOfficeConfig);
  EXPECT_EQ(writeRosbagFromRawlog(rawlog, rawlogReaderOptions(options), prefix + ".bag"), 76u);
  return offlineMap(rawlog, options, prefix + "_offline");
}

TEST_F(StereonavNodeTest, OfficeRunBagGivesTheOfflineMapCellForCell) {
  const nav_msgs::OccupancyGrid offline = officeBagAndOfflineMap(path("office"));
  // 30 captures per second: 6 times the recorded 5 Hz.
  const Playback playback = play(path("office.bag"), kOfficeConfig, 6.0, 76, path("office_node"), false);
  expectSameGrid(playback.map, offline);
  EXPECT_EQ(playback.node_exit_status, 0);
  // Ctrl-C wrote the node's map files: the same as `stereonav map`'s.
  EXPECT_EQ(readFile(path("office_node.pgm")), readFile(path("office_offline.pgm")));
}

// The same with odometry as tf (odom -> base_link) instead of nav_msgs/Odometry: the node looks
// each capture's pose up at its instant.
TEST_F(StereonavNodeTest, OdometryByTfGivesTheSameMap) {
  const nav_msgs::OccupancyGrid offline = officeBagAndOfflineMap(path("office_tf"));
  const Playback playback =
      play(path("office_tf.bag"), kOfficeConfig, 6.0, 76, path("office_tf_node"), false, Odometry::kTf);
  expectSameGrid(playback.map, offline);
}

// A 320x240 trinocular run played at 30 Hz into the node confined to one core: every frame is
// mapped, into the offline map. How long the node still needed after the last message is printed
// (docs/ros.md), not asserted: machines differ.
TEST_F(StereonavNodeTest, ThirtyHertzOf320x240OnOneCoreIsMappedWhole) {
  const std::string config = kSource + "/ini/explore_320x240.ini";
  ASSERT_EQ(runChild({kBinaries + "/stereonav", "simulate", "--world", kSource + "/ini/worlds/table_room.ini",
                      "--config", config, "--path", kSource + "/ini/worlds/table_room_tour.txt",
                      "--out", path("tour.rawlog")}), 0);
  const MappingOptions options = loadMappingOptionsFile(config);
  const size_t frames = writeRosbagFromRawlog(path("tour.rawlog"), rawlogReaderOptions(options), path("tour.bag"));
  ASSERT_GT(frames, 50u);
  const nav_msgs::OccupancyGrid offline = offlineMap(path("tour.rawlog"), options, path("tour_offline"));

  const Playback playback = play(path("tour.bag"), config, 6.0, static_cast<uint32_t>(frames), path("tour_node"), true);
  expectSameGrid(playback.map, offline);
  std::cout << "320x240 at 30 Hz on one core: " << frames << " frames, the last mapped "
            << playback.seconds_after_last_message << " s after the last message\n";
}

}  // namespace
}  // namespace stereonav
