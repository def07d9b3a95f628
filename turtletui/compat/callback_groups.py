"""``rclpy.callback_groups``. turtletui runs every callback in order on one
thread, so both groups behave as mutually exclusive; that is deterministic and
never less safe than ROS."""


class CallbackGroup:
    def __init__(self) -> None:
        self.entities: set = set()

    def add_entity(self, entity) -> None:
        self.entities.add(entity)

    def has_entity(self, entity) -> bool:
        return entity in self.entities

    def can_execute(self, entity) -> bool:
        return True


class MutuallyExclusiveCallbackGroup(CallbackGroup):
    pass


class ReentrantCallbackGroup(CallbackGroup):
    pass
