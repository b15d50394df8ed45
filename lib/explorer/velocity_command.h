#pragma once

namespace stereonav {

// What the explorer asks of a differential-drive base for one control cycle (MRPT's
// CVehicleVelCmd_DiffDriven: lin_vel, ang_vel).
struct VelocityCommand {
  double speed = 0.0;      // m/s, negative reversing
  double turn_rate = 0.0;  // rad/s, positive anticlockwise
};

}  // namespace stereonav
