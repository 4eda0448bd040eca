"""Element dynamics at speed: masses, centrifugal forces, gyroscopic moments, ball kinematics with a
raceway-control hypothesis at unequal inner and outer contact angles. SI units throughout."""
