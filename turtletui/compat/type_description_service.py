"""``rclpy.type_description_service.TypeDescriptionService``: a node's
``~/get_type_description`` service (ROS 2 Iron on).

As rclpy 9's, it declares the read-only ``start_type_description_service``
parameter (true unless overridden) and, if true, serves the descriptions of
the types the node uses (turtletui.graph.type_description_service) as a
service of the node, ``<node name>/get_type_description``, whose callback runs
in the node's default callback group when the node spins.
"""

from __future__ import annotations

import weakref
from typing import Any

from turtletui.compat.distro import current_distro, type_description_names
from turtletui.compat.logging import get_logger
from turtletui.compat.parameter import Parameter
from turtletui.graph.type_description_service import PARAMETER, SERVICE, answer, types_in_use
from turtletui.interfaces.rcl_interfaces import ParameterDescriptor, ParameterType
from turtletui.interfaces.type_description_interfaces import GetTypeDescription

START_TYPE_DESCRIPTION_SERVICE_PARAM = PARAMETER


class TypeDescriptionService:
    """Optionally serves ``node``'s ``~/get_type_description`` (part of every Node)."""

    def __init__(self, node: Any) -> None:
        self._node_weak_ref = weakref.ref(node)
        self.service_name = f"{node.get_name()}/{SERVICE}"
        self._names = type_description_names(current_distro()) or ()
        self._service: Any = None
        self.enabled = False
        if not node.has_parameter(PARAMETER):
            descriptor = ParameterDescriptor(
                name=PARAMETER,
                type=ParameterType.PARAMETER_BOOL,
                description="If enabled, start the ~/get_type_description service.",
                read_only=True,
            )
            node.declare_parameter(PARAMETER, True, descriptor)
        param = node.get_parameter(PARAMETER)
        if param.type_ == Parameter.Type.BOOL:
            self.enabled = param.value
        elif param.type_ != Parameter.Type.NOT_SET:
            node.get_logger().error(f"Invalid type for parameter '{PARAMETER}' {param.type_!r} should be bool")
        if self.enabled and not node.count_services(self.service_name):
            # (a second node of the same name: DDS would have both, one answers)
            self._service = node.create_service(GetTypeDescription, self.service_name, self._service_callback)

    def _service_callback(self, request: Any, response: Any) -> Any:
        node = self._get_node()
        in_use = types_in_use(node._graph, node._record)
        return answer(request, in_use, self._names, get_logger("rcl").error)

    def _get_node(self) -> Any:
        node = self._node_weak_ref()
        if node is None:
            raise ReferenceError("Expected valid node weak reference")
        return node
