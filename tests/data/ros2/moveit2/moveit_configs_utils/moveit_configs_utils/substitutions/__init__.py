from .xacro import Xacro
