"""Robot demonstrations from generated scenes: the Panda at the support edge, grasps, goals, planning, datasets."""
