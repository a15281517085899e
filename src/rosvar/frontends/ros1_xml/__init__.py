"""frontends/ros1_xml."""
