"""``rclpy.lifecycle``: managed nodes, as rclpy 9 and rcl_lifecycle make them.

A LifecycleNode starts "unconfigured" and moves through rcl_lifecycle's
default state machine (configure, activate, deactivate, cleanup, shutdown;
errors go through "errorprocessing") by ``trigger_*`` calls or its services
``<node>/change_state``, ``get_state``, ``get_available_states``,
``get_available_transitions`` and ``get_transition_graph``. Every step is
published on ``<node>/transition_event``. A LifecyclePublisher sends only
while its node is active.

Where rclpy is silent about a student's mistake (a transition callback that
raises, a publish while inactive), turtletui says once why, in a
[turtletui] line.
"""

from __future__ import annotations

import functools
from collections.abc import Callable
from enum import Enum
from typing import Any, NamedTuple

from turtletui.compat.logging import get_logger
from turtletui.compat.node import Node, Publisher
from turtletui.compat.rcl_error import RCLError
from turtletui.graph.logs import WARN
from turtletui.interfaces.lifecycle_msgs import (
    ChangeState,
    GetAvailableStates,
    GetAvailableTransitions,
    GetState,
    State,
    TransitionDescription,
    TransitionEvent,
)


class TransitionCallbackReturnType(Enum):
    """What a transition callback returns (rclpy.lifecycle.TransitionCallbackReturn)."""

    SUCCESS = 97
    FAILURE = 98
    ERROR = 99

    def __int__(self) -> int:
        return self.value

    __index__ = __int__

    def to_label(self) -> str:
        """The label of the transition this result takes (``transition_success`` ...)."""
        return f"transition_{self.name.lower()}"


TransitionCallbackReturn = TransitionCallbackReturnType


class LifecycleState(NamedTuple):
    """A state as a transition callback receives it: the state the node was in."""

    label: str
    state_id: int


_STATES = (
    (0, "unknown"), (1, "unconfigured"), (2, "inactive"), (3, "active"), (4, "finalized"),
    (10, "configuring"), (11, "cleaningup"), (12, "shuttingdown"), (13, "activating"),
    (14, "deactivating"), (15, "errorprocessing"),
)
_LABELS = dict(_STATES)
_TRANSITIONS = (
    (1, "configure", 1, 10), (10, "transition_success", 10, 2), (11, "transition_failure", 10, 1),
    (12, "transition_error", 10, 15),
    (2, "cleanup", 2, 11), (20, "transition_success", 11, 1), (21, "transition_failure", 11, 2),
    (22, "transition_error", 11, 15),
    (3, "activate", 2, 13), (30, "transition_success", 13, 3), (31, "transition_failure", 13, 2),
    (32, "transition_error", 13, 15),
    (4, "deactivate", 3, 14), (40, "transition_success", 14, 2), (41, "transition_failure", 14, 3),
    (42, "transition_error", 14, 15),
    (5, "shutdown", 1, 12), (6, "shutdown", 2, 12), (7, "shutdown", 3, 12),
    (50, "transition_success", 12, 4), (51, "transition_failure", 12, 4), (52, "transition_error", 12, 15),
    (60, "transition_success", 15, 1), (61, "transition_failure", 15, 4), (62, "transition_error", 15, 4),
)
"""rcl_lifecycle's default state machine: (transition id, label, start state, goal state), in its order."""
_CALLBACKS = {10: "on_configure", 11: "on_cleanup", 12: "on_shutdown", 13: "on_activate",
              14: "on_deactivate", 15: "on_error"}
"""The callback that runs on entering each transition state."""


class LifecycleStateMachine:
    """rcl_lifecycle's state machine of one node (what ``node._state_machine`` is in rclpy)."""

    def __init__(self, on_transition: Callable[[int, int], None]) -> None:
        self._state = 1
        self._on_transition = on_transition
        self.initialized = True

    @property
    def current_state(self) -> tuple[int, str]:
        return self._state, _LABELS[self._state]

    @property
    def available_states(self) -> list[tuple[int, str]]:
        return list(_STATES)

    @property
    def available_transitions(self) -> list[tuple[int, str, int, str, int, str]]:
        return [_describe(t) for t in _TRANSITIONS if t[2] == self._state]

    @property
    def transition_graph(self) -> list[tuple[int, str, int, str, int, str]]:
        return [_describe(t) for t in _TRANSITIONS]

    def get_transition_by_label(self, label: str) -> int:
        for transition_id, name, start, _ in _TRANSITIONS:
            if start == self._state and name == label:
                return transition_id
        _no_transition(label, self._state)
        raise RCLError(f"No transition matching {label} found for current state {_LABELS[self._state]}")

    def trigger_transition_by_id(self, transition_id: int, publish_update: bool = True) -> None:
        for known, _, start, goal in _TRANSITIONS:
            if known == transition_id and start == self._state:
                self._move(goal, publish_update)
                return
        _no_transition(transition_id, self._state)
        raise RCLError(f"No transition matching {transition_id} found for current state {_LABELS[self._state]}")

    def trigger_transition_by_label(self, label: str, publish_update: bool = True) -> None:
        self.trigger_transition_by_id(self.get_transition_by_label(label), publish_update)

    def _move(self, goal: int, publish_update: bool) -> None:
        start, self._state = self._state, goal
        if publish_update:
            self._on_transition(start, goal)


def _describe(transition: tuple[int, str, int, int]) -> tuple[int, str, int, str, int, str]:
    transition_id, label, start, goal = transition
    return transition_id, label, start, _LABELS[start], goal, _LABELS[goal]


def _no_transition(what: int | str, state: int) -> None:
    get_logger("rcl_lifecycle").warning(f"No transition matching {what} found for current state {_LABELS[state]}")


class ManagedEntity:
    """Something whose transition callbacks a LifecycleNode calls; each succeeds by default."""

    def on_configure(self, state: LifecycleState) -> TransitionCallbackReturnType:
        return TransitionCallbackReturn.SUCCESS

    def on_cleanup(self, state: LifecycleState) -> TransitionCallbackReturnType:
        return TransitionCallbackReturn.SUCCESS

    def on_shutdown(self, state: LifecycleState) -> TransitionCallbackReturnType:
        return TransitionCallbackReturn.SUCCESS

    def on_activate(self, state: LifecycleState) -> TransitionCallbackReturnType:
        return TransitionCallbackReturn.SUCCESS

    def on_deactivate(self, state: LifecycleState) -> TransitionCallbackReturnType:
        return TransitionCallbackReturn.SUCCESS

    def on_error(self, state: LifecycleState) -> TransitionCallbackReturnType:
        return TransitionCallbackReturn.SUCCESS


class SimpleManagedEntity(ManagedEntity):
    """A managed entity that is enabled while its node is active."""

    def __init__(self) -> None:
        self._enabled = False

    def on_activate(self, state: LifecycleState) -> TransitionCallbackReturnType:
        self._enabled = True
        return TransitionCallbackReturn.SUCCESS

    def on_deactivate(self, state: LifecycleState) -> TransitionCallbackReturnType:
        self._enabled = False
        return TransitionCallbackReturn.SUCCESS

    @property
    def is_activated(self) -> bool:
        return self._enabled

    @staticmethod
    def when_enabled(wrapped: Callable | None = None, *, when_not_enabled: Callable[[], None] | None = None) -> Any:
        """Decorate a method to run only while the entity is enabled (else
        ``when_not_enabled()`` runs, if given)."""

        def decorator(method: Callable) -> Callable:
            @functools.wraps(method)
            def only_when_enabled(self: SimpleManagedEntity, *args: Any, **kwargs: Any) -> None:
                if not self._enabled:
                    if when_not_enabled is not None:
                        when_not_enabled()
                    return
                method(self, *args, **kwargs)

            return only_when_enabled

        return decorator if wrapped is None else decorator(wrapped)


class LifecyclePublisher(SimpleManagedEntity, Publisher):
    """A publisher that sends only while its lifecycle node is active."""

    def __init__(self, *args: Any, **kwargs: Any) -> None:
        SimpleManagedEntity.__init__(self)
        Publisher.__init__(self, *args, **kwargs)
        self._told_inactive = False

    def publish(self, msg: Any) -> None:
        """Publish ``msg`` if the node is active; else nothing is sent, as in rclpy."""
        if self._enabled:
            Publisher.publish(self, msg)
        elif not self._told_inactive:
            self._told_inactive = True
            node = self._node.get_fully_qualified_name()
            self._graph.log("turtletui", WARN, _INACTIVE.format(node=node, topic=self.topic_name))


_INACTIVE = (
    "{node} published on {topic} while its lifecycle publisher is not activated, so nothing was sent "
    "(rclpy drops it silently): activate the node first (trigger_activate() or ros2 lifecycle set)."
)
_RAISED = (
    "{node}'s {callback}() raised {error}: rclpy turns that into TransitionCallbackReturn.ERROR "
    "(on_error() runs next) and shows nothing."
)


class LifecycleNodeMixin(ManagedEntity):
    """What makes a Node a lifecycle node; mixed in before Node (see LifecycleNode)."""

    def __init__(self, *, enable_communication_interface: bool = True, callback_group: Any = None) -> None:
        if not isinstance(self, Node):
            raise RuntimeError("LifecycleNodeMixin uses Node fields so Node needs to be in the inheritance tree.")
        self._managed_entities: set[ManagedEntity] = set()
        self._transition_event_publisher: Publisher | None = None
        self._state_machine = LifecycleStateMachine(self.__publish_transition)
        if not enable_communication_interface:
            return
        for srv_type, name, callback in (
            (ChangeState, "change_state", self.__on_change_state),
            (GetState, "get_state", self.__on_get_state),
            (GetAvailableStates, "get_available_states", self.__on_get_available_states),
            (GetAvailableTransitions, "get_available_transitions", self.__on_get_available_transitions),
            (GetAvailableTransitions, "get_transition_graph", self.__on_get_transition_graph),
        ):
            self.create_service(srv_type, f"~/{name}", callback, callback_group=callback_group)
        self._transition_event_publisher = self.create_publisher(TransitionEvent, "~/transition_event", 10)
        self._transition_event_publisher._told_undiscovered = True  # rcl's own: no note blames the student

    # -- transitions --------------------------------------------------------------
    def trigger_configure(self) -> TransitionCallbackReturnType:
        return self.__change_state(1)

    def trigger_cleanup(self) -> TransitionCallbackReturnType:
        return self.__change_state(2)

    def trigger_activate(self) -> TransitionCallbackReturnType:
        return self.__change_state(3)

    def trigger_deactivate(self) -> TransitionCallbackReturnType:
        return self.__change_state(4)

    def trigger_shutdown(self) -> TransitionCallbackReturnType:
        shutdown = {1: 5, 2: 6, 3: 7}.get(self._state_machine.current_state[0])
        if shutdown is None:
            raise RCLError("Shutdown transtion not possible")  # sic, as rclpy
        return self.__change_state(shutdown)

    def __change_state(self, transition_id: int) -> TransitionCallbackReturnType:
        machine = self._state_machine
        state_id, label = machine.current_state
        previous = LifecycleState(label=label, state_id=state_id)
        try:
            machine.trigger_transition_by_id(transition_id, True)
        except RCLError:
            self.get_logger().error(
                f"Unable to start transition {transition_id} from current state {machine.current_state}"
            )
            return TransitionCallbackReturn.ERROR
        code = self.__execute_callback(machine.current_state[0], previous)
        machine.trigger_transition_by_label(code.to_label(), True)
        if code is TransitionCallbackReturn.ERROR:
            error_code = self.__execute_callback(machine.current_state[0], previous)
            machine.trigger_transition_by_label(error_code.to_label(), True)
        return code

    def __execute_callback(self, state_id: int, previous: LifecycleState) -> TransitionCallbackReturnType:
        name = _CALLBACKS[state_id]
        try:
            code = getattr(self, name)(previous)
        except Exception as err:  # noqa: BLE001  (rclpy: any exception is an ERROR result)
            error = f"{type(err).__name__}: {err}" if str(err) else type(err).__name__
            node = self.get_fully_qualified_name()
            self._graph.log("turtletui", WARN, _RAISED.format(node=node, callback=name, error=error))
            return TransitionCallbackReturn.ERROR
        if not isinstance(code, TransitionCallbackReturnType):
            raise TypeError(
                f"{name}() must return TransitionCallbackReturn.SUCCESS, FAILURE or ERROR, got {code!r}"
            )
        return code

    def __publish_transition(self, start: int, goal: int) -> None:
        if self._transition_event_publisher is not None:
            event = TransitionEvent(start_state=State(id=start, label=_LABELS[start]),
                                    goal_state=State(id=goal, label=_LABELS[goal]))
            self._transition_event_publisher.publish(event)

    # -- managed entities ---------------------------------------------------------
    def add_managed_entity(self, entity: ManagedEntity) -> None:
        if not isinstance(entity, ManagedEntity):
            raise TypeError("Expected a rclpy.lifecycle.ManagedEntity instance.")
        self._managed_entities.add(entity)

    def __entities_callback(self, name: str, state: LifecycleState) -> TransitionCallbackReturnType:
        for entity in list(self._managed_entities):
            code = getattr(entity, name)(state)
            if not isinstance(code, TransitionCallbackReturnType):
                raise TypeError(
                    f"{name}() return value of class {type(entity)} should be `TransitionCallbackReturn`.\n"
                    f"Instance of the class that caused the failure: {entity}"
                )
            if code is not TransitionCallbackReturn.SUCCESS:
                return code
        return TransitionCallbackReturn.SUCCESS

    def on_configure(self, state: LifecycleState) -> TransitionCallbackReturnType:
        """Call every managed entity's on_configure (the default; call super() when overriding)."""
        return self.__entities_callback("on_configure", state)

    def on_cleanup(self, state: LifecycleState) -> TransitionCallbackReturnType:
        return self.__entities_callback("on_cleanup", state)

    def on_shutdown(self, state: LifecycleState) -> TransitionCallbackReturnType:
        return self.__entities_callback("on_shutdown", state)

    def on_activate(self, state: LifecycleState) -> TransitionCallbackReturnType:
        """Call every managed entity's on_activate: activates the lifecycle publishers."""
        return self.__entities_callback("on_activate", state)

    def on_deactivate(self, state: LifecycleState) -> TransitionCallbackReturnType:
        return self.__entities_callback("on_deactivate", state)

    def on_error(self, state: LifecycleState) -> TransitionCallbackReturnType:
        return self.__entities_callback("on_error", state)

    def create_lifecycle_publisher(
        self, msg_type: Any, topic: str, qos_profile: Any, *, publisher_class: None = None, **kwargs: Any
    ) -> LifecyclePublisher:
        """A publisher that sends only while the node is active."""
        if publisher_class:
            raise TypeError("create_publisher() got an unexpected keyword argument 'publisher_class'")
        publisher = Node.create_publisher(
            self, msg_type, topic, qos_profile, publisher_class=LifecyclePublisher, **kwargs
        )
        self._managed_entities.add(publisher)
        return publisher

    def destroy_lifecycle_publisher(self, publisher: LifecyclePublisher) -> bool:
        self._managed_entities.discard(publisher)
        return self.destroy_publisher(publisher)

    # -- services -----------------------------------------------------------------
    def __on_change_state(self, request: Any, response: Any) -> Any:
        transition_id = request.transition.id
        if request.transition.label:
            try:
                transition_id = self._state_machine.get_transition_by_label(request.transition.label)
            except RCLError:
                response.success = False
                return response
        response.success = self.__change_state(transition_id) is TransitionCallbackReturn.SUCCESS
        return response

    def __on_get_state(self, request: Any, response: Any) -> Any:
        response.current_state.id, response.current_state.label = self._state_machine.current_state
        return response

    def __on_get_available_states(self, request: Any, response: Any) -> Any:
        response.available_states = [State(id=i, label=label) for i, label in self._state_machine.available_states]
        return response

    def __on_get_available_transitions(self, request: Any, response: Any) -> Any:
        response.available_transitions = _descriptions(self._state_machine.available_transitions)
        return response

    def __on_get_transition_graph(self, request: Any, response: Any) -> Any:
        response.available_transitions = _descriptions(self._state_machine.transition_graph)
        return response


def _descriptions(transitions: list[tuple[int, str, int, str, int, str]]) -> list[TransitionDescription]:
    found = []
    for transition_id, label, start_id, start_label, goal_id, goal_label in transitions:
        item = TransitionDescription()
        item.transition.id, item.transition.label = transition_id, label
        item.start_state.id, item.start_state.label = start_id, start_label
        item.goal_state.id, item.goal_state.label = goal_id, goal_label
        found.append(item)
    return found


class LifecycleNode(LifecycleNodeMixin, Node):
    """A managed node: Node with LifecycleNodeMixin's states, services and callbacks."""

    def __init__(self, node_name: str, *, enable_communication_interface: bool = True, **kwargs: Any) -> None:
        Node.__init__(self, node_name, **kwargs)
        LifecycleNodeMixin.__init__(self, enable_communication_interface=enable_communication_interface)
