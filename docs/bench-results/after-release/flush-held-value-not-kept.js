(async () => {
  const container = window._JUPYTERLAB && window._JUPYTERLAB['jupyter-matplotlib'];
  const model = (await container.get('./index'))().MPLCanvasModel;
  let proto = model.prototype;
  while (proto && !Object.prototype.hasOwnProperty.call(proto, 'send_sync_message')) proto = Object.getPrototypeOf(proto);
  if (!proto) return 'no WidgetModel';
  const held = new Set();
  const sync = proto.sync;
  proto.sync = function (...args) {
    const result = sync.apply(this, args);
    if (this._msg_buffer !== null) held.add(this);
    return result;
  };
  const flush = () => held.forEach((m) => {
    held.delete(m);
    if (m._msg_buffer !== null && m.comm_live) {
      const id = m.send_sync_message(m._msg_buffer, m._msg_buffer_callbacks);
      m.rememberLastUpdateFor(id);
      m._msg_buffer = null;
      m._msg_buffer_callbacks = null;
      window.__flushed = (window.__flushed || 0) + 1;
    }
  });
  const later = () => setTimeout(flush, 0);
  window.addEventListener('pointerup', later, true);
  window.addEventListener('keyup', later, true);
  return 'patched';
})()
