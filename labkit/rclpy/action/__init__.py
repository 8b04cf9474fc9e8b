"""rclpy.action (Humble): ActionServer, ActionClient and action graph queries."""
from .client import ActionClient  # noqa: F401
from .graph import get_action_client_names_and_types_by_node  # noqa: F401
from .graph import get_action_names_and_types  # noqa: F401
from .graph import get_action_server_names_and_types_by_node  # noqa: F401
from .server import ActionServer, CancelResponse, GoalResponse  # noqa: F401
