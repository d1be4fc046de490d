// The catalog page's search box. The scoring is the catalog library's SearchScore compiled to
// WebAssembly (search_module.cpp), given each entry's search fields as `koppel catalog find
// --text` reads them: the page finds and ranks what the command does. Entries of one score keep
// the catalog's order; an empty query shows every entry.
(function () {
  const fields = JSON.parse(document.getElementById('search-fields').textContent);
  const box = document.getElementById('search');
  const count = document.getElementById('count');
  const list = document.getElementById('entries');
  const cards = Array.from(list.querySelectorAll('.entry'));
  const packed = fields.map((f) => f.map(([text, weight]) => weight + '\t' + text).join('\n'));
  let score = null;

  function show() {
    const query = box.value.trim();
    const order = cards.map((card, i) => ({ card, i, s: query && score ? score(packed[i], query) : 1 }));
    order.sort((a, b) => (b.s - a.s) || (a.i - b.i));
    let shown = 0;
    for (const { card, s } of order) {
      card.hidden = s === 0;
      if (s > 0) shown++;
      list.appendChild(card);
    }
    count.textContent = query ? `${shown} of ${cards.length} entries match “${query}”` : `${cards.length} entries`;
  }
  window.koppelCatalog = { score: (query) => cards.map((c, i) => [c.id, score(packed[i], query)]) };

  if (typeof KoppelSearch === 'undefined') {
    box.disabled = true;
    box.placeholder = 'This koppel was built without the search module (em++): no search';
    show();
    return;
  }
  KoppelSearch().then((module) => {
    score = (f, q) => module.ccall('koppel_search_score', 'number', ['string', 'string'], [f, q]);
    window.koppelCatalog.ready = true;
    box.addEventListener('input', show);
    show();
  });
  show();
})();
