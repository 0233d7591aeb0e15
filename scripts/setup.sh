# Shared set-up for the README's commands (scripts/demo, scripts/test): sourced, not run.
# Installs the Debian 12 packages the project needs (once), then builds the catkin workspace
# .ws/ (this repository linked as .ws/src/thin_ice_sim). Idempotent: a second call installs
# nothing and catkin_make rebuilds only what changed.

# Debian's ROS 1 tools are python3 scripts with '#!/usr/bin/env python3'; a pyenv python3 first
# on PATH lacks catkin_pkg and rospy, so /usr/bin goes first.
export PATH=/usr/bin:/bin:/usr/sbin:/sbin:$PATH

THIN_ICE_ROOT=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
THIN_ICE_WS="$THIN_ICE_ROOT/.ws"

# One apt line: ROS 1 from Debian's own packages (no /opt/ros), the core's libraries, the tools
# for plots and the headless rviz screenshot, and Slurm with munge for scripts/study validate --slurm
# (the test brings up its own one-node cluster; no daemon is started by the install).
THIN_ICE_APT_PACKAGES="catkin ros-message-generation ros-message-runtime \
  libroscpp-dev ros-std-msgs libstd-msgs-dev ros-geometry-msgs libgeometry-msgs-dev \
  ros-visualization-msgs libvisualization-msgs-dev ros-std-srvs libstd-srvs-dev \
  ros-rosgraph-msgs libros-rosgraph-msgs-dev \
  libdynamic-reconfigure-config-init-mutex-dev python3-dynamic-reconfigure \
  libtf2-dev libtf2-ros-dev libtf2-geometry-msgs-dev libtf2-eigen-dev \
  python3-roslaunch python3-rosmaster rosout python3-rostest librostest-dev \
  python3-rosbag librosbag-dev rosbash rospack-tools python3-rostopic python3-rosnode \
  python3-rosservice python3-rosmsg python3-std-msgs python3-std-srvs python3-geometry-msgs \
  python3-visualization-msgs python3-tf2-msgs python3-tf2-ros tf2-tools python3-numpy \
  python3-yaml python3-matplotlib \
  libeigen3-dev libcgal-dev libgmp-dev libmpfr-dev libyaml-cpp-dev libboost-dev \
  googletest libgtest-dev libbenchmark-dev libnanoflann-dev cmake g++ make \
  slurm-wlm munge"

thin_ice_install() {
  local missing
  missing=$(dpkg-query -W -f='${Package} ${Status}\n' $THIN_ICE_APT_PACKAGES 2>/dev/null \
              | awk '$4 != "installed" {print $1}')
  # dpkg-query prints nothing for packages it has never heard of: count those as missing too.
  for p in $THIN_ICE_APT_PACKAGES; do
    dpkg-query -W "$p" >/dev/null 2>&1 || missing="$missing $p"
  done
  missing=$(echo $missing | tr ' ' '\n' | sort -u | tr '\n' ' ')
  if [ -z "${missing// /}" ]; then
    echo "[setup] all Debian packages present"
    return 0
  fi
  echo "[setup] installing:$missing"
  if [ "$(id -u)" != 0 ]; then
    echo "[setup] error: packages are missing and this is not root; run as root or install them" >&2
    return 1
  fi
  export DEBIAN_FRONTEND=noninteractive
  apt-get update -q || return 1
  apt-get install -y -q --no-install-recommends $missing || return 1
}

thin_ice_build() {
  mkdir -p "$THIN_ICE_WS/src"
  [ -L "$THIN_ICE_WS/src/thin_ice_sim" ] || ln -s ../.. "$THIN_ICE_WS/src/thin_ice_sim"
  export ROS_HOME="$THIN_ICE_WS/ros_home"
  export ROS_LOG_DIR="$ROS_HOME/log"
  mkdir -p "$ROS_LOG_DIR"
  local cuda_args=()
  if [ -x /usr/local/cuda/bin/nvcc ]; then
    cuda_args=(-DCMAKE_CUDA_COMPILER=/usr/local/cuda/bin/nvcc)
  fi
  (cd "$THIN_ICE_WS" && catkin_make -DCMAKE_BUILD_TYPE=Release "${cuda_args[@]}" \
      -j"$(nproc)" "$@") || return 1
  # catkin's setup scripts read unset variables: source them with 'set -u' off.
  local flags=$-
  set +u
  # shellcheck disable=SC1091
  source "$THIN_ICE_WS/devel/setup.bash"
  [[ $flags == *u* ]] && set -u
  return 0
}
