"""Fixtures of the workspace helpers launch files call and the files they read (issue 28,
items 3 and 4): the methods of substitution objects, builders over ``pathlib`` paths, launch
actions subclassed in a workspace module, for :mod:`.test_fixtures` to compare with the
oracle (which has the fixture's package on its ``PYTHONPATH``)."""

from __future__ import annotations

Case = tuple[dict[str, str], list[dict[str, str]]]

CASES: dict[str, Case] = {
    "python-find-package-method": (
        {
            "main.launch.py": """import os
from launch import LaunchDescription
from launch_ros.actions import Node
from launch_ros.substitutions import FindPackagePrefix, FindPackageShare


def generate_launch_description():
    share = FindPackageShare('pkg').find('pkg')
    prefix = FindPackagePrefix(package='pkg').find(package_name='pkg')
    return LaunchDescription([
        Node(package='pkg', executable='talker', name='t',
             parameters=[{'share': os.path.join(share, 'config'), 'prefix': prefix}]),
    ])
"""
        },
        [{}],
    ),
    "python-subclassed-launch-actions": (
        {
            "pkg_helpers/__init__.py": "",
            "pkg_helpers/launch_utils.py": """from launch.actions import DeclareLaunchArgument
from launch.conditions import IfCondition, UnlessCondition
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node


class DeclareSwitch(DeclareLaunchArgument):
    def __init__(self, switch, on=False, **rest):
        super().__init__(switch, default_value='true' if on else 'false',
                         choices=['false', 'true'], **rest)


class PlainNode(Node):
    pass


class DebugNode(Node):
    def __init__(self, flag, **kwargs):
        super().__init__(condition=IfCondition(LaunchConfiguration(flag)), **kwargs)
        self.flag = flag


def add_debuggable(ld, executable):
    ld.add_action(Node(package='pkg', executable=executable,
                       condition=UnlessCondition(LaunchConfiguration('debug'))))
    ld.add_action(DebugNode('debug', package='pkg', executable=executable,
                            name='debug_' + executable))
""",
            "main.launch.py": """from launch import LaunchDescription
from pkg_helpers.launch_utils import DeclareSwitch, PlainNode, add_debuggable


def generate_launch_description():
    ld = LaunchDescription()
    ld.add_action(DeclareSwitch('debug'))
    ld.add_action(DeclareSwitch('extra', on=True))
    add_debuggable(ld, 'talker')
    ld.add_action(PlainNode(package='pkg', executable='listener', name='plain'))
    return ld
""",
        },
        [{}, {"debug": "true"}, {"debug": "false", "extra": "false"}],
    ),
    "python-builder-over-pathlib": (
        {
            "config/kinematics.yaml": "arm:\n  solver: kdl\n  timeout: 0.005\n",
            "config/ompl_planning.yaml": "planner: rrt\n",
            "config/notes.txt": "not a configuration\n",
            "pkg_builder/__init__.py": "",
            "pkg_builder/builder.py": """import logging
import re
from pathlib import Path

import yaml
from ament_index_python.packages import get_package_share_directory


def load_yaml(file_path):
    if not file_path.exists():
        raise KeyError(str(file_path))
    with open(file_path, 'r') as file:
        return yaml.load(file, Loader=yaml.FullLoader)


class Builder:
    __config = Path('config')

    def __init__(self, package):
        self._path = Path(get_package_share_directory(package))
        self.__parameters = {}

    def kinematics(self, file_path=None):
        self.__parameters['robot_description_kinematics'] = load_yaml(
            self._path / (file_path or self.__config / 'kinematics.yaml'))
        return self

    def pipelines(self):
        folder = self._path / self.__config
        pattern = re.compile('^(.*)_planning.yaml$')
        names = []
        for child in folder.iterdir():
            if not child.is_file():
                continue
            found = pattern.search(child.name)
            if found:
                names.append(found.groups()[0])
        if not (folder / 'missing.yaml').exists():
            logging.warning('no missing.yaml in %s', folder)
        for name in names:
            self.__parameters[name] = load_yaml(folder / (name + '_planning.yaml'))
        self.__parameters['pipelines'] = names
        return self

    def to_dict(self):
        return self.__parameters
""",
            "main.launch.py": """from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node
from pkg_builder.builder import Builder


def generate_launch_description():
    rate = LaunchConfiguration('rate')
    parameters = Builder('pkg').kinematics().pipelines().to_dict()
    mappings = {'rate': rate} if isinstance(rate, str) else {'given': 'yes'}
    return LaunchDescription([
        DeclareLaunchArgument('rate', default_value='10'),
        Node(package='pkg', executable='talker', name='builder',
             parameters=[parameters, mappings, {'rate': rate}]),
    ])
""",
        },
        [{}, {"rate": "2.5"}],
    ),
    "python-getenv-branches": (
        {
            "main.launch.py": """import os
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node


def generate_launch_description():
    nodes = [DeclareLaunchArgument('robot', default_value='r1')]
    if os.getenv('ROSVAR_TEST_SIM', 'false') == 'true':
        nodes.append(Node(package='pkg', executable='sim', name='sim'))
    else:
        robot = os.environ.get('ROSVAR_TEST_ROBOT', 'r0')
        nodes.append(Node(package='pkg', executable='real', name=f'real_{robot}',
                          parameters=[{'robot': LaunchConfiguration('robot')}]))
    return LaunchDescription(nodes)
""",
        },
        [{}, {"robot": "r2"}],
    ),
    "python-file-named-by-an-argument": (
        {
            "config/fusion.param.yaml": """/**:
  ros__parameters:
    topics: [/sensing/lidar/top/points, /sensing/lidar/left/points]
    shared: {resolution: 0.5, length: [150.0, 120.0]}
""",
            "main.launch.py": """import yaml
from ament_index_python.packages import get_package_share_directory
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, OpaqueFunction
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node


def load(context, name):
    path = LaunchConfiguration(name).perform(context)
    with open(path, 'r') as f:
        return yaml.safe_load(f)['/**']['ros__parameters']


def setup(context):
    config = load(context, 'config_file')
    nodes = []
    for i in range(len(config['topics'])):
        frame = config['topics'][i].split('/')[-2]
        shared = dict(config['shared'])
        shared['length'] = max(shared['length'])
        nodes.append(Node(package='pkg', executable='grid', name='grid_' + frame,
                          namespace=frame, parameters=[shared, {'index': i}],
                          remappings=[('input', config['topics'][i])]))
    return nodes


def generate_launch_description():
    return LaunchDescription([
        DeclareLaunchArgument('config_file', default_value=get_package_share_directory('pkg')
                              + '/config/fusion.param.yaml'),
        DeclareLaunchArgument('flag', default_value='false'),
        OpaqueFunction(function=setup),
    ])
""",
        },
        [{}, {"flag": "true"}],
    ),
    "python-getenv-returns-a-description-in-each-branch": (
        {
            "main.launch.py": """import os
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node


def generate_launch_description():
    declared = [DeclareLaunchArgument('camera', default_value='cam')]
    distro = os.getenv('ROSVAR_TEST_DISTRO')
    if (distro == 'dashing') or (distro == 'eloquent'):
        return LaunchDescription(declared + [
            Node(package='pkg', node_executable='old', node_name=LaunchConfiguration('camera'))])
    else:
        return LaunchDescription(declared + [
            Node(package='pkg', executable='new', name=LaunchConfiguration('camera'))])
""",
        },
        [{}, {"camera": "front"}],
    ),
    "python-path-parts-of-launch-time-paths": (
        {
            "main.launch.py": """import os
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, OpaqueFunction
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node


def nodes(context):
    path = LaunchConfiguration('map').perform(context)
    home = os.getenv('ROSVAR_TEST_UNSET', '/q/r/x/y')
    return [Node(package='pkg', executable='map_server', name='maps',
                 parameters=[{'dir': os.path.dirname(path), 'file': os.path.basename(path),
                              'home': f"{os.path.dirname(home)}/z"}])]


def generate_launch_description():
    return LaunchDescription([
        DeclareLaunchArgument('map', default_value='/maps/lab/map.yaml'),
        OpaqueFunction(function=nodes),
    ])
""",
        },
        [{}, {"map": "office.yaml"}, {"map": "/srv/maps/"}],
    ),
    "python-getenv-unset": (
        {
            "main.launch.py": """import os
from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    nodes = []
    if os.getenv('ROSVAR_TEST_UNSET') == 'foxy':
        nodes.append(Node(package='pkg', executable='old', name='old'))
    else:
        distro = os.environ.get('ROSVAR_TEST_UNSET') or 'jazzy'
        nodes.append(Node(package='pkg', executable='new', name='new',
                          parameters=[{'distro': distro}]))
    return LaunchDescription(nodes)
""",
        },
        [{}],
    ),
    "python-helper-writes-a-parameter-file": (
        {
            "config/robot.yaml": """planner:
  ros__parameters:
    rate: 1.0
    frame: map
    limits: {speed: 0.5, turn: 1}
tracker:
  ros__parameters:
    rate: 4
    frame: odom
""",
            "config/template.yaml": """tracker:
  ros__parameters:
    topic: <ns>/scan
""",
            "pkg_helpers/__init__.py": "from .files import Rewritten, Replaced\n",
            "pkg_helpers/files.py": """import tempfile

import launch
import yaml
from launch.utilities import normalize_to_list_of_substitutions, perform_substitutions


class Slot:
    def __init__(self, mapping, key):
        self.mapping = mapping
        self.key = key

    def put(self, value):
        self.mapping[self.key] = value


def slots(data):
    try:
        for key in data.keys():
            yield from slots(data[key])
            yield Slot(data, key)
    except AttributeError:
        return


class Rewritten(launch.Substitution):
    def __init__(self, source, values, under=None, typed=False):
        super().__init__()
        self.__source = normalize_to_list_of_substitutions(source)
        self.__values = {k: normalize_to_list_of_substitutions(v) for k, v in values.items()}
        self.__under = None if under is None else normalize_to_list_of_substitutions(under)
        self.__typed = typed

    @property
    def source(self):
        return self.__source

    def typed(self, text):
        if self.__typed:
            try:
                return float(text) if '.' in text else int(text)
            except ValueError:
                pass
        if text.lower() in ('true', 'false'):
            return text.lower() == 'true'
        return text

    def perform(self, context):
        with open(perform_substitutions(context, self.source)) as stream:
            data = yaml.safe_load(stream)
        values = {k: perform_substitutions(context, v) for k, v in self.__values.items()}
        for slot in slots(data):
            if slot.key in values:
                slot.put(self.typed(values[slot.key]))
        if self.__under is not None:
            under = perform_substitutions(context, self.__under)
            if under:
                data = {under: data}
        written = tempfile.NamedTemporaryFile(mode='w', delete=False)
        yaml.dump(data, written)
        written.close()
        return written.name


class Replaced(launch.Substitution):
    def __init__(self, source, replacements, condition=None):
        super().__init__()
        self.__source = normalize_to_list_of_substitutions(source)
        self.__replacements = replacements
        self.__condition = condition

    def perform(self, context):
        if self.__condition is not None and not self.__condition.evaluate(context):
            return perform_substitutions(context, self.__source)
        pairs = {k: perform_substitutions(context, normalize_to_list_of_substitutions(v))
                 for k, v in self.__replacements.items()}
        written = tempfile.NamedTemporaryFile(mode='w', delete=False)
        for line in open(perform_substitutions(context, self.__source)):
            for key, value in pairs.items():
                line = line.replace(key, value)
            written.write(line)
        written.close()
        return written.name
""",
            "main.launch.py": """import os
from ament_index_python.packages import get_package_share_directory
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch.conditions import IfCondition
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node
from launch_ros.descriptions import ParameterFile
from pkg_helpers import Replaced, Rewritten


def generate_launch_description():
    share = get_package_share_directory('pkg')
    ns = LaunchConfiguration('ns')
    rewritten = ParameterFile(
        Rewritten(LaunchConfiguration('params'), under=ns, typed=True,
                  values={'rate': LaunchConfiguration('rate'), 'speed': '0.75',
                          'frame': LaunchConfiguration('frame')}),
        allow_substs=True)
    replaced = Replaced(os.path.join(share, 'config', 'template.yaml'), {'<ns>': ('/', ns)})
    renamed = Replaced(LaunchConfiguration('params'), {'map': 'world'},
                       condition=IfCondition(LaunchConfiguration('rename')))
    chained = Rewritten(renamed, values={'rate': '9'})
    return LaunchDescription([
        DeclareLaunchArgument('ns', default_value=''),
        DeclareLaunchArgument('rate', default_value='2'),
        DeclareLaunchArgument('frame', default_value='True'),
        DeclareLaunchArgument('rename', default_value='false'),
        DeclareLaunchArgument('params',
                              default_value=os.path.join(share, 'config', 'robot.yaml')),
        Node(package='pkg', executable='planner', name='planner', namespace=ns,
             parameters=[rewritten]),
        Node(package='pkg', executable='tracker', name='tracker', namespace=ns,
             parameters=[rewritten, replaced]),
        Node(package='pkg', executable='planner', name='planner', namespace='chained',
             parameters=[chained]),
    ])
""",
        },
        [{}, {"ns": "r1", "rate": "2.5", "frame": "base"}, {"rate": "fast", "rename": "true"}],
    ),
}
