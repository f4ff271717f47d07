"""``--dask local`` starts even while another cluster holds the dashboard's usual port 8787
(CI saw two test workers' LocalClusters race for it: "Cluster failed to start: Port 8787 is
already in use")."""

from __future__ import annotations

import socket
import warnings

from camlab88.apps.snooker.film.backends import DaskCluster


def test_a_local_cluster_does_not_need_port_8787() -> None:
    holder = socket.socket()
    try:
        holder.bind(("127.0.0.1", 8787))  # as another cluster's dashboard would
        holder.listen()
    except OSError:
        pass  # someone already holds it: the same situation
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("error")  # "Port 8787 is already in use" is a warning
            cluster = DaskCluster(scene=None, address="local", workers=1)
        try:
            assert cluster.workers == 1
        finally:
            cluster.close()
    finally:
        holder.close()
