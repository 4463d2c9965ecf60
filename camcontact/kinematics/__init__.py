"""Cam kinematics: motion programs composed of motion-law segments, and follower kinematics."""
