"""Differential tests: rosvar's restriction to one configuration against the real roslaunch."""
